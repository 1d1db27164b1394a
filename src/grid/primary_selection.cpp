#include "grid/primary_selection.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace cutaway::grid {
namespace {

void require_values(const CornerPointGrid& grid, const std::vector<float>& values, const std::string& name) {
    if (values.size() != grid.cell_count())
        throw std::invalid_argument("property " + name + ": " + std::to_string(values.size()) +
                                    " values, expected one per cell (" + std::to_string(grid.cell_count()) + ")");
}

/// `value` (NaN or an infinity) in active cell `cell`: no colour or selection can hold it.
[[noreturn]] void throw_non_finite(const CornerPointGrid& grid, const std::string& name, std::size_t cell, float value) {
    const CellIjk c = cell_ijk(grid.dims(), cell);
    const std::string shown = std::isnan(value) ? "NaN" : value > 0 ? "inf" : "-inf";
    throw std::invalid_argument("property " + name + ": " + shown + " in active cell (i,j,k) = (" + std::to_string(c.i) +
                                "," + std::to_string(c.j) + "," + std::to_string(c.k) + "), expected a finite number");
}

/// Active cells' values, checked to be finite.
std::vector<float> active_values(const CornerPointGrid& grid, const std::vector<float>& values, const std::string& name) {
    require_values(grid, values, name);
    std::vector<float> out;
    out.reserve(grid.active_count());
    for (std::size_t cell = 0; cell < values.size(); ++cell) {
        if (!grid.active(cell)) continue;
        if (!std::isfinite(values[cell])) throw_non_finite(grid, name, cell, values[cell]);
        out.push_back(values[cell]);
    }
    return out;
}

}  // namespace

std::vector<std::uint8_t> select_primaries(const CornerPointGrid& grid, const std::vector<float>& values,
                                           const std::string& property_name, const PrimaryRange& range,
                                           const std::optional<IjkBox>& box) {
    require_values(grid, values, property_name);
    std::vector<std::uint8_t> flags(grid.cell_count(), 0);
    for (std::size_t cell = 0; cell < values.size(); ++cell) {
        if (!grid.active(cell)) continue;
        const float v = values[cell];
        if (!std::isfinite(v)) throw_non_finite(grid, property_name, cell, v);
        if (v < range.min || v > range.max) continue;
        if (box && !box->contains(cell_ijk(grid.dims(), cell))) continue;
        flags[cell] = 1;
    }
    return flags;
}

void check_fraction(double fraction) {
    if (!(fraction > 0 && fraction <= 1))
        throw std::invalid_argument("primary fraction " + std::to_string(fraction) + ": expected a value in (0, 1]");
}

std::size_t primary_count_for_fraction(double fraction, std::size_t active) {
    return std::max<std::size_t>(1, std::size_t(std::llround(fraction * double(active))));
}

PrimaryRange range_for_fraction(const CornerPointGrid& grid, const std::vector<float>& values,
                                const std::string& property_name, double fraction) {
    check_fraction(fraction);
    std::vector<float> active = active_values(grid, values, property_name);
    if (active.empty()) throw std::invalid_argument("property " + property_name + ": the grid has no active cell");
    const std::size_t wanted = primary_count_for_fraction(fraction, active.size());
    const auto nth = active.begin() + std::ptrdiff_t(active.size() - wanted);
    std::nth_element(active.begin(), nth, active.end());
    const float top = *std::max_element(nth, active.end());
    return {*nth, top};
}

void check_finite_active(const CornerPointGrid& grid, const std::vector<float>& values, const std::string& property_name) {
    require_values(grid, values, property_name);
    for (std::size_t cell = 0; cell < values.size(); ++cell)
        if (grid.active(cell) && !std::isfinite(values[cell])) throw_non_finite(grid, property_name, cell, values[cell]);
}

PrimaryRange active_value_range(const CornerPointGrid& grid, const std::vector<float>& values,
                                const std::string& property_name) {
    const std::vector<float> active = active_values(grid, values, property_name);
    if (active.empty()) return {0, 0};
    const auto [lo, hi] = std::minmax_element(active.begin(), active.end());
    return {*lo, *hi};
}

PrimaryRange active_quantile_range(const CornerPointGrid& grid, const std::vector<float>& values,
                                   const std::string& property_name, double lo_fraction, double hi_fraction,
                                   bool positive_only) {
    std::vector<float> active = active_values(grid, values, property_name);
    if (positive_only) active.erase(std::remove_if(active.begin(), active.end(), [](float v) { return !(v > 0); }), active.end());
    if (active.empty()) return {0, 0};
    const auto at = [&](double fraction) {
        const auto nth = active.begin() + std::ptrdiff_t(std::llround(std::clamp(fraction, 0.0, 1.0) * double(active.size() - 1)));
        std::nth_element(active.begin(), nth, active.end());
        return *nth;
    };
    const float lo = at(lo_fraction);
    return {lo, at(hi_fraction)};
}

std::size_t count_primaries(const std::vector<std::uint8_t>& flags) {
    return std::size_t(std::count(flags.begin(), flags.end(), std::uint8_t(1)));
}

}  // namespace cutaway::grid

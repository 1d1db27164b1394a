#pragma once
// The primary set of a cutaway: active cells whose property lies in [min, max], optionally
// restricted to an IJK box. Everything else active is secondary.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "grid/corner_point_grid.h"

namespace cutaway::grid {

/// Inclusive cell-index box (0-based).
struct IjkBox {
    int i0 = 0, j0 = 0, k0 = 0;
    int i1 = 0, j1 = 0, k1 = 0;
    bool contains(const CellIjk& c) const {
        return c.i >= i0 && c.i <= i1 && c.j >= j0 && c.j <= j1 && c.k >= k0 && c.k <= k1;
    }
    /// The box's own dimensions (cells along each axis).
    GridDims dims() const { return {i1 - i0 + 1, j1 - j0 + 1, k1 - k0 + 1}; }
    /// Every cell of a grid of `d`.
    static IjkBox whole(const GridDims& d) { return {0, 0, 0, d.nx - 1, d.ny - 1, d.nz - 1}; }
    bool operator==(const IjkBox&) const = default;
};

struct PrimaryRange {
    float min = 0;
    float max = 0;
};

/// One flag per cell (cell_count() entries): 1 = primary. Inactive cells are never primary.
/// `values`: one value per cell (NaN in an active cell is an error: throws std::invalid_argument
/// naming `property_name` and the cell's i,j,k).
std::vector<std::uint8_t> select_primaries(const CornerPointGrid& grid, const std::vector<float>& values,
                                           const std::string& property_name, const PrimaryRange& range,
                                           const std::optional<IjkBox>& box = std::nullopt);

/// The range [v, max] whose cells make up about `fraction` (0, 1] of the active cells: the top
/// fraction by value (ties at v are all included, so the count may exceed the target).
PrimaryRange range_for_fraction(const CornerPointGrid& grid, const std::vector<float>& values,
                                const std::string& property_name, double fraction);

/// Throws std::invalid_argument unless `fraction` lies in (0, 1].
void check_fraction(double fraction);
/// How many of `active` cells range_for_fraction aims at (at least 1).
std::size_t primary_count_for_fraction(double fraction, std::size_t active);

/// Throws std::invalid_argument naming the property and the cell when an active cell's value is
/// NaN or infinite (inactive cells may hold anything: nothing reads them).
void check_finite_active(const CornerPointGrid& grid, const std::vector<float>& values, const std::string& property_name);

/// Min and max of `values` over active cells (throws on NaN or infinity, naming the property and cell).
PrimaryRange active_value_range(const CornerPointGrid& grid, const std::vector<float>& values,
                                const std::string& property_name);

/// The `lo_fraction` and `hi_fraction` quantiles (0..1, nearest rank) of `values` over active cells,
/// only positive ones when `positive_only` (a logarithmic colour scale); {0, 0} when none is left.
/// A colour range from them is not stretched by a few outliers, as min and max are.
PrimaryRange active_quantile_range(const CornerPointGrid& grid, const std::vector<float>& values,
                                   const std::string& property_name, double lo_fraction, double hi_fraction,
                                   bool positive_only);

std::size_t count_primaries(const std::vector<std::uint8_t>& flags);

}  // namespace cutaway::grid

#include "generator_parameters.h"

#include <charconv>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace cutaway::generators {
namespace {

std::string text(double value) {
    char buffer[32];
    return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}

void require(bool ok, const std::string& message) {
    if (!ok) throw std::invalid_argument("generate: " + message);
}

void require_fraction(double value, const std::string& name) {
    require(std::isfinite(value) && value >= 0 && value < 1,
            name + " must lie in [0, 1) (a share of the cells), got " + text(value));
}

void require_positive(double value, const std::string& name, const std::string& unit) {
    require(std::isfinite(value) && value > 0, name + " must be positive (" + unit + "), got " + text(value));
}

}  // namespace

std::vector<std::string> describe(const GeneratorParameters& p) {
    return {
        "generator = cutaway generate (synthetic faulted corner-point model)",
        "preset = " + p.name,
        "dims = " + std::to_string(p.dims.nx) + " " + std::to_string(p.dims.ny) + " " + std::to_string(p.dims.nz) +
            " (" + std::to_string(p.dims.cell_count()) + " cells)",
        "extent_m = " + text(p.length_x) + " " + text(p.length_y) + " " + text(p.thickness),
        "top_depth_m = " + text(p.top_depth),
        "seed = " + std::to_string(p.seed),
        "faults = " + std::to_string(p.fault_count),
        "throw_range_m = " + text(p.throw_range.first) + " " + text(p.throw_range.second),
        "fault_dip_deg = " + text(p.fault_dip_deg),
        "fault_azimuth_deg = " + text(p.fault_azimuth_deg),
        "fault_azimuth_spread_deg = " + text(p.fault_azimuth_spread_deg),
        "lean_spread_pillars = " + std::to_string(p.lean_spread_pillars),
        "horizon_roughness_m = " + text(p.horizon_roughness),
        "pinch_out_fraction = " + text(p.pinch_out_fraction),
        "inactive_fraction = " + text(p.inactive_fraction),
        "poro_mean = " + text(p.poro_mean),
        "poro_std = " + text(p.poro_std),
        "poro_correlation_length_m = " + text(p.poro_correlation_length),
        "time_steps = " + std::to_string(p.time_steps),
        "injectors = " + std::to_string(p.injector_count),
    };
}

std::size_t estimated_peak_bytes(const GeneratorParameters& p) {
    const double cells = double(p.dims.cell_count());
    const double columns = double(p.dims.nx) * double(p.dims.ny);
    // In doubles: (NX+1) overflows int for NX = 2^31-1 (an estimate of 18446744073.7 GB).
    const double pillars = (double(p.dims.nx) + 1) * (double(p.dims.ny) + 1);
    // Compact ZCORN (4 doubles per column and interface), pillar interface depths (up to two
    // variants per pillar), per-cell arrays: ACTNUM, PORO, PERMX, NTG, FACIES, SWAT steps, the
    // front's arrival times and queue, and the fields the properties are drawn from.
    const double zcorn = 4 * columns * (p.dims.nz + 1) * 8.0;
    const double interfaces = 2 * pillars * (p.dims.nz + 1) * 8.0;
    const double per_cell = 1 + 4 * 4 + 4.0 * p.time_steps + 4 + 16 + 8;
    const double bytes = 1.15 * (zcorn + interfaces + per_cell * cells) + 64e6;
    return bytes >= double(std::numeric_limits<std::size_t>::max()) ? std::numeric_limits<std::size_t>::max()
                                                                     : std::size_t(bytes);
}

void validate(const GeneratorParameters& p, std::size_t memory_limit_bytes) {
    require(p.dims.nx > 0 && p.dims.ny > 0 && p.dims.nz > 0,
            "dims must be positive, got " + std::to_string(p.dims.nx) + " " + std::to_string(p.dims.ny) + " " +
                std::to_string(p.dims.nz));
    require(p.dims.cell_count() <= std::size_t(std::numeric_limits<std::int32_t>::max()),
            "at most 2^31-1 cells, got " + std::to_string(p.dims.cell_count()));
    require_positive(p.length_x, "extent x", "metres");
    require_positive(p.length_y, "extent y", "metres");
    require_positive(p.thickness, "thickness", "metres");
    require(std::isfinite(p.top_depth), "top depth must be finite");
    require(p.fault_count >= 0 && p.fault_count <= 64,
            "faults must be between 0 and 64, got " + std::to_string(p.fault_count));
    require(std::isfinite(p.throw_range.first) && std::isfinite(p.throw_range.second) && p.throw_range.first >= 0 &&
                p.throw_range.first <= p.throw_range.second,
            "throw range must satisfy 0 <= min <= max (metres), got " + text(p.throw_range.first) + " " +
                text(p.throw_range.second));
    require(p.throw_range.second < p.thickness,
            "throw " + text(p.throw_range.second) + " m is larger than the model (thickness " + text(p.thickness) +
                " m): a fault would offset a block past the whole reservoir");
    require(std::isfinite(p.fault_dip_deg) && p.fault_dip_deg >= 30 && p.fault_dip_deg <= 90,
            "fault dip must lie in [30, 90] degrees from horizontal, got " + text(p.fault_dip_deg));
    require(std::isfinite(p.fault_azimuth_deg), "fault azimuth must be finite");
    require(std::isfinite(p.fault_azimuth_spread_deg) && p.fault_azimuth_spread_deg >= 0 &&
                p.fault_azimuth_spread_deg <= 90,
            "fault azimuth spread must lie in [0, 90] degrees, got " + text(p.fault_azimuth_spread_deg));
    require(p.lean_spread_pillars >= 0 && p.lean_spread_pillars <= 16,
            "lean spread must be 0..16 pillars, got " + std::to_string(p.lean_spread_pillars));
    require(std::isfinite(p.horizon_roughness) && p.horizon_roughness >= 0 && p.horizon_roughness <= 10 * p.thickness,
            "horizon roughness must lie in [0, 10 x thickness] metres, got " + text(p.horizon_roughness));
    require_fraction(p.pinch_out_fraction, "pinch-out fraction");
    require_fraction(p.inactive_fraction, "inactive fraction");
    require(p.pinch_out_fraction + p.inactive_fraction < 1,
            "pinch-out fraction + inactive fraction must be below 1 (some cells must stay active)");
    require(std::isfinite(p.poro_mean) && p.poro_mean > 0 && p.poro_mean < 1,
            "porosity mean must lie in (0, 1), got " + text(p.poro_mean));
    require(std::isfinite(p.poro_std) && p.poro_std >= 0 && p.poro_std < 1,
            "porosity std must lie in [0, 1), got " + text(p.poro_std));
    require_positive(p.poro_correlation_length, "porosity correlation length", "metres");
    require(p.time_steps >= 0 && p.time_steps <= 1000,
            "time steps must be 0..1000, got " + std::to_string(p.time_steps));
    require(p.injector_count >= 1 && p.injector_count <= 64,
            "injectors must be 1..64, got " + std::to_string(p.injector_count));
    const std::size_t needed = estimated_peak_bytes(p);
    require(needed <= memory_limit_bytes,
            std::to_string(p.dims.cell_count()) + " cells need about " + text(double(needed) / 1e9) +
                " GB, beyond the memory limit of " + text(double(memory_limit_bytes) / 1e9) +
                " GB (lower dims or time steps, or raise --memory-limit-gb)");
}

}  // namespace cutaway::generators

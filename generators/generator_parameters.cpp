#include "generator_parameters.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "generators/parameter_check.h"

namespace cutaway::generators {
namespace {

void require_fraction(double value, const std::string& option) {
    require_parameter(std::isfinite(value) && value >= 0 && value < 1, option, "a share of the cells in [0, 1)", value);
}

void require_positive(double value, const std::string& option, const std::string& what) {
    require_parameter(std::isfinite(value) && value > 0, option, what, value);
}

}  // namespace

std::vector<std::string> describe(const GeneratorParameters& p) {
    return {
        "generator = cutaway generate (synthetic faulted corner-point model)",
        "preset = " + p.name,
        "dims = " + std::to_string(p.dims.nx) + " " + std::to_string(p.dims.ny) + " " + std::to_string(p.dims.nz) +
            " (" + std::to_string(p.dims.cell_count()) + " cells)",
        "extent_m = " + parameter_text(p.length_x) + " " + parameter_text(p.length_y) + " " + parameter_text(p.thickness),
        "top_depth_m = " + parameter_text(p.top_depth),
        "seed = " + std::to_string(p.seed),
        "faults = " + std::to_string(p.fault_count),
        "throw_range_m = " + parameter_text(p.throw_range.first) + " " + parameter_text(p.throw_range.second),
        "fault_dip_deg = " + parameter_text(p.fault_dip_deg),
        "fault_azimuth_deg = " + parameter_text(p.fault_azimuth_deg),
        "fault_azimuth_spread_deg = " + parameter_text(p.fault_azimuth_spread_deg),
        "lean_spread_pillars = " + std::to_string(p.lean_spread_pillars),
        "horizon_roughness_m = " + parameter_text(p.horizon_roughness),
        "pinch_out_fraction = " + parameter_text(p.pinch_out_fraction),
        "inactive_fraction = " + parameter_text(p.inactive_fraction),
        "poro_mean = " + parameter_text(p.poro_mean),
        "poro_std = " + parameter_text(p.poro_std),
        "poro_correlation_length_m = " + parameter_text(p.poro_correlation_length),
        "time_steps = " + std::to_string(p.time_steps),
        "injectors = " + std::to_string(p.injector_count),
    };
}

std::size_t estimated_peak_bytes(const GeneratorParameters& p) { return estimated_peak_bytes(p, grid::IjkBox::whole(p.dims)); }

std::size_t estimated_peak_bytes(const GeneratorParameters& p, const grid::IjkBox& box) {
    const grid::GridDims b = box.dims();
    const double cells = double(b.cell_count());
    const double columns = double(b.nx) * double(b.ny);
    // In doubles: (NX+1) overflows int for NX = 2^31-1 (an estimate of 18446744073.7 GB).
    const double pillars = (double(b.nx) + 1) * (double(b.ny) + 1);
    const int time_steps = box == grid::IjkBox::whole(p.dims) ? p.time_steps : 0;  // a block has no SWAT
    // Compact ZCORN (4 doubles per column and interface), pillar interface depths (up to two
    // variants per pillar), per-cell arrays: ACTNUM, PORO, PERMX, NTG, FACIES, SWAT steps, the
    // front's arrival times and queue, and the fields the properties are drawn from.
    const double zcorn = 4 * columns * (b.nz + 1) * 8.0;
    const double interfaces = 2 * pillars * (b.nz + 1) * 8.0;
    const double per_cell = 1 + 4 * 4 + 4.0 * time_steps + 4 + 16 + 8;
    const double bytes = 1.15 * (zcorn + interfaces + per_cell * cells) + 64e6;
    return bytes >= double(std::numeric_limits<std::size_t>::max()) ? std::numeric_limits<std::size_t>::max()
                                                                     : std::size_t(bytes);
}

void validate(const GeneratorParameters& p, std::size_t memory_limit_bytes) {
    validate(p, memory_limit_bytes, grid::IjkBox::whole(p.dims));
}

void validate(const GeneratorParameters& p, std::size_t memory_limit_bytes, const grid::IjkBox& box) {
    const std::string dims =
        std::to_string(p.dims.nx) + " " + std::to_string(p.dims.ny) + " " + std::to_string(p.dims.nz);
    require_parameter(p.dims.nx > 0 && p.dims.ny > 0 && p.dims.nz > 0, "--dims", "NX NY NZ, each at least 1", dims);
    require_parameter(p.dims.cell_count() <= std::size_t(std::numeric_limits<std::int32_t>::max()), "--dims",
                      "at most 2^31-1 cells", dims + " = " + std::to_string(p.dims.cell_count()) + " cells");
    require_positive(p.length_x, "--extent", "a positive east extent in metres");
    require_positive(p.length_y, "--extent", "a positive north extent in metres");
    require_positive(p.thickness, "--extent", "a positive thickness in metres");
    require_parameter(std::isfinite(p.top_depth), "--top-depth", "a finite depth in metres", p.top_depth);
    require_parameter(p.fault_count >= 0 && p.fault_count <= 64, "--faults", "an integer in [0, 64]", p.fault_count);
    const std::string throws = parameter_text(p.throw_range.first) + " " + parameter_text(p.throw_range.second);
    require_parameter(std::isfinite(p.throw_range.first) && std::isfinite(p.throw_range.second) &&
                          p.throw_range.first >= 0 && p.throw_range.first <= p.throw_range.second,
                      "--throw", "MIN MAX in metres with 0 <= MIN <= MAX", throws);
    require_parameter(p.throw_range.second < p.thickness, "--throw",
                      "MAX below the model's thickness of " + parameter_text(p.thickness) +
                          " m (a larger throw offsets a block past the whole reservoir)",
                      throws);
    require_parameter(std::isfinite(p.fault_dip_deg) && p.fault_dip_deg >= 30 && p.fault_dip_deg <= 90, "--dip",
                      "a dip in [30, 90] degrees from horizontal", p.fault_dip_deg);
    require_parameter(std::isfinite(p.fault_azimuth_deg), "--azimuth", "a finite angle in degrees", p.fault_azimuth_deg);
    require_parameter(std::isfinite(p.fault_azimuth_spread_deg) && p.fault_azimuth_spread_deg >= 0 &&
                          p.fault_azimuth_spread_deg <= 90,
                      "--azimuth-spread", "an angle in [0, 90] degrees", p.fault_azimuth_spread_deg);
    require_parameter(p.lean_spread_pillars >= 0 && p.lean_spread_pillars <= 16, "--lean-spread",
                      "an integer in [0, 16] pillars", p.lean_spread_pillars);
    require_parameter(std::isfinite(p.horizon_roughness) && p.horizon_roughness >= 0 &&
                          p.horizon_roughness <= 10 * p.thickness,
                      "--roughness", "a relief in [0, 10 x thickness] = [0, " + parameter_text(10 * p.thickness) + "] metres",
                      p.horizon_roughness);
    require_fraction(p.pinch_out_fraction, "--pinch-fraction");
    require_fraction(p.inactive_fraction, "--inactive-fraction");
    require_parameter(p.pinch_out_fraction + p.inactive_fraction < 1, "--pinch-fraction + --inactive-fraction",
                      "a sum below 1 (some cells must stay active)", p.pinch_out_fraction + p.inactive_fraction);
    require_parameter(std::isfinite(p.poro_mean) && p.poro_mean > 0 && p.poro_mean < 1, "--poro-mean",
                      "a porosity mean in (0, 1)", p.poro_mean);
    require_parameter(std::isfinite(p.poro_std) && p.poro_std >= 0 && p.poro_std < 1, "--poro-std",
                      "a porosity standard deviation in [0, 1)", p.poro_std);
    require_positive(p.poro_correlation_length, "--poro-correlation", "a positive correlation length in metres");
    require_parameter(p.time_steps >= 0 && p.time_steps <= 1000, "--time-steps", "an integer in [0, 1000]", p.time_steps);
    require_parameter(p.injector_count >= 1 && p.injector_count <= 64, "--injectors", "an integer in [1, 64]",
                      p.injector_count);
    require_parameter(box.i0 >= 0 && box.j0 >= 0 && box.k0 >= 0 && box.i0 <= box.i1 && box.j0 <= box.j1 &&
                          box.k0 <= box.k1 && box.i1 < p.dims.nx && box.j1 < p.dims.ny && box.k1 < p.dims.nz,
                      "block", "a box of cells within the grid of " + dims,
                      std::to_string(box.i0) + " " + std::to_string(box.j0) + " " + std::to_string(box.k0) + " to " +
                          std::to_string(box.i1) + " " + std::to_string(box.j1) + " " + std::to_string(box.k1));
    const std::size_t needed = estimated_peak_bytes(p, box);
    const double gib = double(1u << 30);
    require_parameter(needed <= memory_limit_bytes, "--memory-limit-gb",
                      "room for " + std::to_string(box.dims().cell_count()) + " cells (about " +
                          parameter_text(std::round(double(needed) / gib * 100) / 100) +
                          " GiB needed: lower --dims or --time-steps, or raise the memory limit)",
                      parameter_text(std::round(double(memory_limit_bytes) / gib * 100) / 100) + " GiB");
}

}  // namespace cutaway::generators

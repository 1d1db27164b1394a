#include "flow_schedule.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "flow_fluid_model.h"
#include "grid/cell_geometry.h"

namespace cutaway::generators {
namespace {

namespace fluids = flow_fluids;

/// Darcy's law in METRIC units: m3/day through 1 m2 per mD, bar/m and 1/cP.
constexpr double kDarcyMetric = 0.008527;
constexpr double kAtmosphereBar = 1.01325;

/// Radial inflow to a well over k h (mD m) times mobility: m3/day per bar between the well and
/// the radius `drainage_radius` (metres) where the flow around it turns linear, half the spacing
/// of the wells along their flank. Peaceman's equivalent radius 0.198 of the cell size (cells of
/// horizontal area `footprint`, m2) is the least: inside it the grid itself resolves nothing.
double well_productivity(double kh, double footprint, double drainage_radius, double mobility) {
    const double r0 = 0.198 * std::sqrt(footprint);
    const double rw = 0.5 * fluids::wellbore_diameter_m;
    return kDarcyMetric * 2 * std::numbers::pi * kh * mobility / std::log(std::max(drainage_radius, r0) / rw);
}

struct Volumes {
    double pore_volume = 0;
    double shallowest_centre = std::numeric_limits<double>::infinity();
    double deepest_corner = -std::numeric_limits<double>::infinity();
};

Volumes active_volumes(const grid::CornerPointGrid& grid) {
    const std::vector<float>* poro = grid.property("PORO");
    const std::vector<float>* ntg = grid.property("NTG");
    if (!poro || !ntg)
        throw std::invalid_argument(std::string("--deck: expected the model's ") + (poro ? "NTG" : "PORO") +
                                    ", found none");
    const grid::GridDims& d = grid.dims();
    Volumes v;
    for (int k = 0; k < d.nz; ++k)
        for (int j = 0; j < d.ny; ++j)
            for (int i = 0; i < d.nx; ++i) {
                const std::size_t cell = d.cell_index(i, j, k);
                if (!grid.active(cell)) continue;
                const grid::CellCorners corners = grid::cell_corners(grid, i, j, k);
                v.pore_volume += grid::cell_volume(corners) * double((*poro)[cell]) * double((*ntg)[cell]);
                v.shallowest_centre = std::min(v.shallowest_centre, grid::cell_centre(corners).z);
                for (const grid::Point3& corner : corners) v.deepest_corner = std::max(v.deepest_corner, corner.z);
            }
    if (!(v.pore_volume > 0))
        throw std::invalid_argument("--deck: expected active cells with pore volume, found none");
    return v;
}

}  // namespace

FlowSchedule plan_flow_schedule(const grid::CornerPointGrid& grid, const WellPlacement& wells) {
    const Volumes volumes = active_volumes(grid);
    FlowSchedule s;
    s.pore_volume_m3 = volumes.pore_volume;
    s.datum_depth_m = volumes.shallowest_centre;
    s.datum_pressure_bar =
        kAtmosphereBar + fluids::pressure_gradient_bar_per_m(fluids::water_density) * s.datum_depth_m;
    s.water_contact_depth_m = volumes.deepest_corner + 10;
    const double oil_gradient = fluids::pressure_gradient_bar_per_m(fluids::oil_density);
    const auto initial_pressure = [&](const ColumnSummary& c) {
        return s.datum_pressure_bar + oil_gradient * (c.top_depth - s.datum_depth_m);
    };

    const double water_mobility = fluids::water_relperm_at_residual_oil / fluids::water_viscosity_cp;
    const double oil_mobility = fluids::oil_relperm_at_connate_water / fluids::oil_viscosity_cp;
    std::vector<double> injectivity;
    double total_injectivity = 0, total_productivity = 0;
    const double injector_radius = 0.5 * wells.injector_spacing, producer_radius = 0.5 * wells.producer_spacing;
    for (const DeckWell& w : wells.injectors) {
        injectivity.push_back(well_productivity(w.column.kh, w.column.footprint, injector_radius, water_mobility));
        total_injectivity += injectivity.back();
    }
    for (const DeckWell& w : wells.producers)
        total_productivity += well_productivity(w.column.kh, w.column.footprint, producer_radius, oil_mobility);
    // Linear flow of oil between the flanks through the field's mean k h across the strike (at
    // least one cell wide).
    const double width = std::max(wells.strike_extent, std::sqrt(wells.injectors.front().column.footprint));
    const double field_resistance = wells.flank_distance / (kDarcyMetric * wells.mean_column_kh * width * oil_mobility);
    const double resistance = 1 / total_injectivity + 1 / total_productivity + field_resistance;  // bar per m3/day
    s.estimated_capacity_m3_day = (kInjectorOverpressureBar + kProducerDrawdownBar) / resistance;

    const double injected_m3 = kInjectedPoreVolumes * s.pore_volume_m3;
    const double days = injected_m3 / (kCapacityShare * s.estimated_capacity_m3_day);
    s.report_steps = kDeckReportSteps;
    // At most a century per step: a model too tight for that gets a rate its injectors cannot reach.
    s.report_step_days = int(std::clamp(std::ceil(days / kDeckReportSteps), 1.0, 36500.0));
    const double rate_m3_day = injected_m3 / (double(s.report_steps) * double(s.report_step_days));
    for (std::size_t w = 0; w < wells.injectors.size(); ++w) {
        s.injection_rate_sm3_day.push_back(rate_m3_day / fluids::water_formation_factor * injectivity[w] /
                                           total_injectivity);
        s.injector_bhp_limit_bar.push_back(initial_pressure(wells.injectors[w].column) + kInjectorOverpressureBar);
    }
    for (const DeckWell& w : wells.producers)
        s.producer_bhp_bar.push_back(initial_pressure(w.column) - kProducerDrawdownBar);
    return s;
}

}  // namespace cutaway::generators

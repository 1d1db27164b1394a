#pragma once
// The generated deck's initial state, well controls and report steps, chosen from the model's
// pore volume and the wells' estimated capacity so the injected water crosses the field within
// the schedule: water is injected at a fixed total rate (split over the injectors by their
// injectivity), producers hold a bottom-hole pressure below the initial pressure.
#include <vector>

#include "flow_well_placement.h"
#include "grid/corner_point_grid.h"

namespace cutaway::generators {

struct FlowSchedule {
    double pore_volume_m3 = 0;        ///< sum of volume * PORO * NTG over active cells
    double datum_depth_m = 0;         ///< centre depth of the shallowest active cell (EQUIL datum)
    double datum_pressure_bar = 0;    ///< hydrostatic (water) pressure at the datum
    double water_contact_depth_m = 0; ///< below every active cell: the whole model starts at Swi
    /// Per injector (placement order): surface water rate, sm3/day, and the bottom-hole pressure
    /// it may not exceed, bar.
    std::vector<double> injection_rate_sm3_day;
    std::vector<double> injector_bhp_limit_bar;
    /// Per producer: the bottom-hole pressure it holds, bar.
    std::vector<double> producer_bhp_bar;
    int report_steps = 0;
    int report_step_days = 0;
    double estimated_capacity_m3_day = 0; ///< reservoir m3/day the wells and field pass at the full pressure window
};

/// Report steps of every generated deck: restarts are written at each.
constexpr int kDeckReportSteps = 30;
/// Water injected by the end of the schedule, in pore volumes (reservoir conditions).
constexpr double kInjectedPoreVolumes = 0.8;
/// Bar above the initial pressure an injector may reach; bar below it a producer holds.
constexpr double kInjectorOverpressureBar = 150;
constexpr double kProducerDrawdownBar = 50;
/// Share of the estimated capacity planned for: the estimate ignores heterogeneity and the
/// water's changing mobility, so the schedule stays clear of the injectors' pressure limit.
constexpr double kCapacityShare = 0.35;

/// Throws std::invalid_argument ("--deck: expected ...") when `grid` lacks PORO or NTG or has no
/// pore volume.
FlowSchedule plan_flow_schedule(const grid::CornerPointGrid& grid, const WellPlacement& wells);

}  // namespace cutaway::generators

#include "wells/restart_wells.h"

namespace cutaway::wells {
namespace {

WellStatus status_named(const std::string& status) {
    if (status == "shut") return WellStatus::shut;
    if (status == "stop") return WellStatus::stop;
    if (status == "auto") return WellStatus::automatic;
    return WellStatus::open;
}

}  // namespace

std::vector<Well> wells_from_restart(const std::vector<eclipse::WellAtStep>& step_wells) {
    std::vector<Well> wells;
    for (const eclipse::WellAtStep& at_step : step_wells) {
        Well well;
        well.name = at_step.name;
        well.head_i = at_step.head_i;
        well.head_j = at_step.head_j;
        well.status = status_named(at_step.status);
        if (at_step.type == "producer") well.kind = WellKind::producer;
        const std::string suffix = "_injector";
        if (at_step.type.size() > suffix.size() && at_step.type.ends_with(suffix)) {
            well.kind = WellKind::injector;
            // water_injector -> WATER, as WCONINJE names the phase.
            for (char c : at_step.type.substr(0, at_step.type.size() - suffix.size())) well.injected_phase += char(c - 'a' + 'A');
        }
        for (const eclipse::ConnectionAtStep& c : at_step.connections) well.connections.push_back({c.i, c.j, c.k, c.open});
        wells.push_back(std::move(well));
    }
    return wells;
}

std::vector<Well> restart_wells(const eclipse::ReportSteps& steps, std::size_t index) {
    return wells_from_restart(steps.wells_with_connections(index));
}

}  // namespace cutaway::wells

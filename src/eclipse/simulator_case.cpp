#include "eclipse/simulator_case.h"

#include <algorithm>

#include "eclipse/egrid_reader.h"
#include "eclipse/init_reader.h"

namespace cutaway::eclipse {

std::size_t memory_left(const grid::CornerPointGrid& grid, std::size_t limit_bytes) {
    return limit_bytes - std::min(limit_bytes, grid.geometry_bytes() + grid.property_bytes());
}

SimulatorCase load_simulator_case(const CaseFiles& files, std::size_t memory_limit_bytes,
                                  const std::optional<std::string>& only_property) {
    SimulatorCase loaded{read_egrid(files.egrid, memory_limit_bytes), nullptr};
    grid::CornerPointGrid& grid = loaded.grid;
    if (files.init) {
        std::optional<std::string> only = only_property;
        if (only && only->empty()) only = "PORO";
        add_init_properties(grid, *files.init, memory_left(grid, memory_limit_bytes), only);
    }
    if (files.unrst) {
        auto steps = std::make_shared<const ReportSteps>(*files.unrst, grid, memory_left(grid, memory_limit_bytes));
        for (const std::string& name : steps->property_names()) grid.declare_dynamic_steps(name, steps->step_count());
        if (grid.metadata().unit_system.empty()) grid.metadata().unit_system = steps->unit_system();
        loaded.report_steps = std::move(steps);
    }
    return loaded;
}

void hold_report_step(grid::CornerPointGrid& grid, const ReportSteps& steps, const std::string& name, std::size_t index) {
    grid.set_dynamic_step(name, index, steps.values(name, index));
}

}  // namespace cutaway::eclipse

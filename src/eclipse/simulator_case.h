#pragma once
// A simulator case as a model: the EGRID's grid with the INIT's static arrays, and the UNRST's
// report steps declared on the grid (none held) for the caller to hold one step at a time.
#include <cstddef>
#include <memory>
#include <optional>
#include <string>

#include "eclipse/case_files.h"
#include "eclipse/report_steps.h"
#include "grid/corner_point_grid.h"

namespace cutaway::eclipse {

struct SimulatorCase {
    grid::CornerPointGrid grid;
    std::shared_ptr<const ReportSteps> report_steps;  ///< null without an UNRST
};

/// Reads `files.egrid`, then `files.init`'s cell arrays (`only_property`: the one wanted, empty
/// for PORO; std::nullopt: all), then `files.unrst`'s step list, declaring each restart array on
/// the grid with the file's step count (grid::CornerPointGrid::declare_dynamic_steps), and the unit
/// system (INIT's INTEHEAD, else UNRST's) in the grid's metadata. Everything
/// within `memory_limit_bytes` (what the grid holds counts against what follows). Throws EclipseError.
SimulatorCase load_simulator_case(const CaseFiles& files, std::size_t memory_limit_bytes,
                                  const std::optional<std::string>& only_property);

/// What is left of `limit_bytes` once `grid` (geometry and properties) is held.
std::size_t memory_left(const grid::CornerPointGrid& grid, std::size_t limit_bytes);

/// Holds step `index` of restart array `name` on `grid` (read through `steps`), releasing the
/// step of `name` held before: the grid holds one step per array. Throws EclipseError.
void hold_report_step(grid::CornerPointGrid& grid, const ReportSteps& steps, const std::string& name, std::size_t index);

}  // namespace cutaway::eclipse

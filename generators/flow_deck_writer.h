#pragma once
// An OPM Flow deck for a generated model: CASE.DATA (RUNSPEC, GRID, PROPS, SOLUTION, SUMMARY,
// SCHEDULE) and the CASE.GRDECL it includes (COORD, ZCORN, ACTNUM, PORO, PERMX, NTG). Two-phase
// oil-water (flow_fluid_model.h), wells placed by the geology (flow_well_placement.h), rates and
// report steps from the pore volume (flow_schedule.h), a restart at every report step.
#include <filesystem>
#include <string>
#include <vector>

#include "flow_schedule.h"
#include "flow_well_placement.h"
#include "grid/corner_point_grid.h"

namespace cutaway::generators {

struct FlowDeckPlan {
    WellPlacement wells;
    FlowSchedule schedule;
};

/// Wells and schedule for `grid` (see place_wells, plan_flow_schedule); throws
/// std::invalid_argument ("--deck: expected ...") for a model no deck can be made of.
FlowDeckPlan plan_flow_deck(const grid::CornerPointGrid& grid);

/// The CASE.DATA text: `header_comments` as `--` lines, then the sections; the grid comes from
/// INCLUDE of `grid_file_name` (beside the DATA file).
std::string flow_deck_text(const grid::GridDims& dims, const FlowDeckPlan& plan, const std::string& grid_file_name,
                           const std::vector<std::string>& header_comments);

/// The two files of a deck in `directory` (created when missing; its parent must exist):
/// CASE.GRDECL and CASE.DATA, each written whole or not at all (io::write_stream).
struct FlowDeckFiles {
    std::filesystem::path data;
    std::filesystem::path grid;
};
FlowDeckFiles flow_deck_files(const std::filesystem::path& directory, const std::string& case_name);

/// Writes both files of `files`; throws io::OutputError naming the file that failed.
void write_flow_deck(const FlowDeckFiles& files, const grid::CornerPointGrid& grid, const FlowDeckPlan& plan,
                     const std::vector<std::string>& header_comments);

/// Lines for the command's report: wells, pore volume, rates, report steps.
std::vector<std::string> describe(const FlowDeckPlan& plan);

}  // namespace cutaway::generators

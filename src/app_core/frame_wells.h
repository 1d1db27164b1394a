#pragma once
// The wells a frame draws (`--wells`, `--well-radius`): read from the --wells FILE or a simulator
// case's restart at the frame's report step, selected by name, with their paths in model units.
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app_core/model_source.h"
#include "volumes/volume_mesh.h"
#include "cutaway/well_tubes.h"
#include "wells/well.h"
#include "wells/well_paths.h"

namespace cutaway::app {

/// --wells (once or twice: a FILE and/or all|none|NAME,...) and --well-radius.
void add_well_options(CLI::App& command, std::vector<std::string>& wells, double& well_radius);

/// Throws CLI::ValidationError naming --wells for values that do not combine (two files, two
/// selections, an empty name): checked while parsing, before any file is read.
void check_well_option(const std::vector<std::string>& wells_values);

/// The wells `wells_values` select, and where they came from (for messages).
struct ChosenWells {
    std::vector<wells::Well> wells;
    std::string source;
};

/// The wells --wells selects on `model` at report step `time_step` (-1: the first): from the FILE
/// (checked against the model's dimensions `dims`), else the simulator case's restart; none when
/// --wells is not given or is `none`. Throws std::invalid_argument for a selection the model has
/// no wells for or an unknown name (listing the known ones), io::BadInputError for a bad file.
ChosenWells choose_wells(const LoadedModel& model, const grid::GridDims& dims, const std::vector<std::string>& wells_values,
                         int time_step);

/// `chosen` with their `paths` (one per well, model units) and the tube radius: `well_radius`
/// when above 0, else `default_radius`.
pipeline::WellSet drawn_wells(const std::vector<wells::Well>& chosen, const std::vector<std::vector<grid::Point3>>& paths,
                              double well_radius, double default_radius);

/// The single-process frame's wells on the whole model `model` (needs its corner depths).
pipeline::WellSet frame_wells(const LoadedModel& model, const std::vector<std::string>& wells_values, double well_radius,
                              int time_step);

/// Every well of the model with its path (model units), for `well:NAME` cut volumes whatever
/// --wells draws: the --wells FILE's, else the simulator case's restart at `time_step`; empty when
/// the model has none (a `well:` volume is then refused as unknown). Needs the corner depths.
volumes::WellPaths cut_volume_well_paths(const LoadedModel& model, const std::vector<std::string>& wells_values,
                                         int time_step);

/// The paths of the wells `set` draws, by name.
volumes::WellPaths paths_of(const pipeline::WellSet& set);

/// The wells of report steps first..last for an animation (the restart's wells step by step; one
/// set for a FILE or none), built before the renderer releases the corner depths.
class StepWellSets {
public:
    StepWellSets(const LoadedModel& model, const std::vector<std::string>& wells_values, double well_radius,
                 std::size_t first, std::size_t last);
    /// The set shown at report step `step` (first..last).
    const pipeline::WellSet& at(std::size_t step) const { return sets_[per_step_ ? step - first_ : 0]; }
    /// Whether the set shown changes from step `a` to step `b`.
    bool changes(std::size_t a, std::size_t b) const { return per_step_ && a != b; }

private:
    bool per_step_ = false;
    std::size_t first_ = 0;
    std::vector<pipeline::WellSet> sets_;
};

}  // namespace cutaway::app

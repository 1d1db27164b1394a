#include "app_core/frame_wells.h"

#include <stdexcept>

#include "app_core/option_checks.h"
#include "grid/cell_geometry.h"
#include "wells/deck_wells.h"
#include "wells/restart_wells.h"
#include "wells/well_selection.h"

namespace cutaway::app {

void check_well_option(const std::vector<std::string>& wells_values) {
    try {
        (void)wells::parse_wells_option(wells_values);
    } catch (const std::invalid_argument& e) {
        throw CLI::ValidationError("--wells", e.what());
    }
}

void add_well_options(CLI::App& c, std::vector<std::string>& wells, double& well_radius) {
    c.add_option("--wells", wells,
                 "wells drawn as tubes, named at their wellheads: all | none | NAME[,NAME...] (a simulator case's "
                 "restart at the shown step), and/or a deck FILE whose WELSPECS and COMPDAT define them (default: none)")
        ->expected(1)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
        ->check(utf8_text());
    // 1e9 model units is beyond any model's extent.
    c.add_option("--well-radius", well_radius, "well tube radius, model units (0: a fifth of the median cell width)")
        ->check(finite_in(0, 1e9));
}

ChosenWells choose_wells(const LoadedModel& model, const grid::GridDims& dims, const std::vector<std::string>& wells_values,
                         int time_step) {
    const wells::WellsOption option = wells::parse_wells_option(wells_values);
    if (!option.draws()) return {};
    ChosenWells chosen;
    if (option.file) {
        chosen.source = option.file->string();
        chosen.wells = wells::read_deck_wells(*option.file);
        wells::check_within_grid(chosen.wells, dims, chosen.source);
    } else if (const auto& steps = model.report_steps ? model.report_steps : model.block_wells_restart) {
        const std::size_t step = std::size_t(std::max(time_step, 0));
        if (step >= steps->step_count())
            throw std::invalid_argument("--time-step " + std::to_string(step) + ": the case has " +
                                        std::to_string(steps->step_count()) + " report steps (0-based)");
        chosen.source = steps->file().string() + " at report step " + std::to_string(step);
        chosen.wells = wells::restart_wells(*steps, step);
        wells::check_within_grid(chosen.wells, dims, chosen.source);
    } else {
        throw std::invalid_argument("--wells: " + model.description +
                                    " holds no wells (only a simulator case's restart does): name a deck with --wells FILE");
    }
    chosen.wells = wells::select_wells(chosen.wells, option, chosen.source);
    return chosen;
}

pipeline::WellSet drawn_wells(const std::vector<wells::Well>& chosen, const std::vector<std::vector<grid::Point3>>& paths,
                              double well_radius, double default_radius) {
    pipeline::WellSet set;
    set.radius = well_radius > 0 ? well_radius : default_radius;
    for (std::size_t w = 0; w < chosen.size(); ++w) {
        const auto colour = wells::well_colour(chosen[w]);
        set.wells.push_back({chosen[w].name, paths[w], {colour[0], colour[1], colour[2]}});
    }
    return set;
}

pipeline::WellSet frame_wells(const LoadedModel& model, const std::vector<std::string>& wells_values, double well_radius,
                              int time_step) {
    const ChosenWells chosen = choose_wells(model, model.grid.dims(), wells_values, time_step);
    if (chosen.wells.empty()) return {};
    const grid::Box3 bounds = grid::grid_bounds(model.grid);
    const wells::WellheadLevel level = wells::wellhead_level(bounds, model.grid.depth_direction());
    std::vector<std::vector<grid::Point3>> paths;
    for (const wells::Well& well : chosen.wells) paths.push_back(wells::well_path(well, model.grid, level));
    return drawn_wells(chosen.wells, paths, well_radius, wells::default_well_radius(model.grid, bounds));
}

volumes::WellPaths cut_volume_well_paths(const LoadedModel& model, const std::vector<std::string>& wells_values,
                                         int time_step) {
    const wells::WellsOption option = wells::parse_wells_option(wells_values);
    if (!option.file && !model.report_steps) return {};  // no wells to read
    std::vector<std::string> every{"all"};
    if (option.file) every.insert(every.begin(), option.file->string());
    const ChosenWells chosen = choose_wells(model, model.grid.dims(), every, time_step);
    const wells::WellheadLevel level = wells::wellhead_level(grid::grid_bounds(model.grid), model.grid.depth_direction());
    volumes::WellPaths paths;
    for (const wells::Well& well : chosen.wells) paths[well.name] = wells::well_path(well, model.grid, level);
    return paths;
}

volumes::WellPaths paths_of(const pipeline::WellSet& set) {
    volumes::WellPaths paths;
    for (const pipeline::DrawnWell& well : set.wells) paths[well.name] = well.path;
    return paths;
}

StepWellSets::StepWellSets(const LoadedModel& model, const std::vector<std::string>& wells_values, double well_radius,
                           std::size_t first, std::size_t last)
    : first_(first) {
    const wells::WellsOption option = wells::parse_wells_option(wells_values);
    per_step_ = option.draws() && !option.file && model.report_steps;
    for (std::size_t step = first; step <= (per_step_ ? last : first); ++step)
        sets_.push_back(frame_wells(model, wells_values, well_radius, int(step)));
}

}  // namespace cutaway::app

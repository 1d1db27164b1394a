#include "app_core/model_source.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "eclipse/case_files.h"
#include "eclipse/egrid_reader.h"
#include "eclipse/init_reader.h"
#include "eclipse/simulator_case.h"
#include "eclipse/step_clock.h"
#include "generators/generator.h"
#include "generators/presets.h"
#include "grid/grdecl_reader.h"
#include "grid/grid_box.h"

namespace cutaway::app {
namespace {

const std::string preset_prefix = "preset:";

bool is_preset(const std::vector<std::string>& model) {
    if (model.empty()) throw std::invalid_argument("no model given: expected a GRDECL file or preset:NAME");
    return model.front().rfind(preset_prefix, 0) == 0;
}

/// The parameters of `model`'s preset (one preset:NAME argument).
generators::GeneratorParameters preset_parameters(const std::vector<std::string>& model) {
    if (model.size() > 1) throw std::invalid_argument(model.front() + ": a preset takes no further files");
    const std::string name = model.front().substr(preset_prefix.size());
    const auto& known = generators::presets();
    const auto preset = std::find_if(known.begin(), known.end(), [&](const auto& p) { return p.name == name; });
    if (preset == known.end())
        throw std::invalid_argument(model.front() + ": expected preset:NAME with NAME one of " +
                                    generators::preset_names() + ", found '" + name + "'");
    return *preset;
}

/// The simulator case `model` names (one CASE.EGRID or CASE argument), if it names one.
std::optional<eclipse::CaseFiles> simulator_case(const std::vector<std::string>& model) {
    if (model.size() == 1) return eclipse::find_case_files(model.front());
    for (const std::string& file : model)
        if (const auto files = eclipse::find_case_files(file); files && files->egrid == std::filesystem::path(file))
            throw std::invalid_argument(file + ": a simulator case takes no further files (CASE.INIT and CASE.UNRST "
                                               "are read from beside it)");
    return std::nullopt;
}

std::string case_description(const eclipse::CaseFiles& files, const LoadedModel& loaded) {
    std::string text = files.egrid.string();
    text += files.init ? " + " + files.init->filename().string() : std::string(" (no INIT)");
    if (loaded.report_steps)
        text += " + " + files.unrst->filename().string() + " (" + std::to_string(loaded.report_steps->step_count()) +
                " report steps)";
    else
        text += " (no UNRST)";
    return text;
}

LoadedModel load_case(const eclipse::CaseFiles& files, std::size_t memory_limit_bytes,
                      const std::optional<std::string>& only_property) {
    eclipse::SimulatorCase simulator = eclipse::load_simulator_case(files, memory_limit_bytes, only_property);
    LoadedModel loaded;
    loaded.grid = std::move(simulator.grid);
    loaded.report_steps = std::move(simulator.report_steps);
    loaded.init_file = files.init;
    loaded.description = case_description(files, loaded);
    return loaded;
}

/// The restart array `property` (empty: the default) names in `model`, or empty when it is none.
std::string restart_array(const LoadedModel& model, const std::string& property) {
    if (!model.report_steps) return {};
    const std::string name = property.empty() ? default_property_name(model.grid) : property;
    return model.report_steps->has_property(name) ? name : std::string();
}

std::vector<std::filesystem::path> files_of(const std::vector<std::string>& model) {
    return {model.begin(), model.end()};
}

std::string files_description(const std::vector<std::string>& model) {
    std::string description;
    for (const std::string& file : model) description += (description.empty() ? "" : " + ") + file;
    return description;
}

/// Reading options within `memory_limit_bytes` that refuse an INCLUDE naming one of `outputs`.
grid::GrdeclReadOptions read_options(std::size_t memory_limit_bytes, const std::vector<io::NamedFile>& outputs) {
    grid::GrdeclReadOptions options;
    options.memory_limit_bytes = memory_limit_bytes;
    if (!outputs.empty())
        options.before_include = [outputs](const std::filesystem::path& include, const std::string& where) {
            if (const std::string problem = io::overwrite_problem({{"the INCLUDE at " + where, include.string()}}, outputs);
                !problem.empty())
                throw std::invalid_argument(problem);
        };
    return options;
}

double seconds_since(std::chrono::steady_clock::time_point started) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
}

}  // namespace

LoadedModel load_model(const std::vector<std::string>& model, std::size_t memory_limit_bytes,
                       const std::optional<std::string>& only_property, const std::vector<io::NamedFile>& outputs) {
    const auto started = std::chrono::steady_clock::now();
    LoadedModel loaded;
    if (const auto files = simulator_case(model)) {
        loaded = load_case(*files, memory_limit_bytes, only_property);
    } else if (is_preset(model)) {
        generators::GeneratorParameters parameters = preset_parameters(model);
        const bool without_flood = only_property && *only_property != generators::generated_dynamic_property;
        if (without_flood) parameters.time_steps = 0;
        generators::ProgressLog quiet(nullptr);
        loaded.grid = generators::generate_model(parameters, quiet, memory_limit_bytes).grid;
        loaded.description = model.front() + " (seed " + std::to_string(parameters.seed) +
                             (without_flood ? ", no " + generators::generated_dynamic_property + " steps: not asked for" : "") + ")";
    } else {
        loaded.grid = grid::load_grdecl(files_of(model), read_options(memory_limit_bytes, outputs), &loaded.warnings);
        loaded.description = files_description(model);
    }
    loaded.load_seconds = seconds_since(started);
    return loaded;
}

std::vector<io::NamedFile> model_input_files(const std::vector<std::string>& model) {
    std::vector<io::NamedFile> files;
    if (model.empty() || is_preset(model)) return files;
    for (const std::string& file : model) files.push_back({"the model", file});
    return files;
}

std::string default_property_name(const grid::CornerPointGrid& grid) {
    if (grid.property("PORO")) return "PORO";
    if (const auto statics = grid.property_names(); !statics.empty()) return statics.front();
    if (const auto dynamics = grid.dynamic_property_names(); !dynamics.empty()) return dynamics.front();
    return {};
}

bool holds_time_step(const LoadedModel& model, const std::string& property, int time_step) {
    const std::string array = restart_array(model, property);
    return array.empty() || model.grid.dynamic_property(array, std::size_t(std::max(time_step, 0))) != nullptr;
}

void hold_property(LoadedModel& model, const std::string& property, int time_step, std::size_t memory_limit_bytes) {
    const std::string name = property.empty() ? default_property_name(model.grid) : property;
    const bool unread = !model.grid.property(name) && !model.grid.int_property(name) && restart_array(model, name).empty();
    if (model.init_file && unread)
        eclipse::add_init_properties(model.grid, *model.init_file, eclipse::memory_left(model.grid, memory_limit_bytes), name);
    if (holds_time_step(model, property, time_step)) return;
    const std::size_t step = std::size_t(std::max(time_step, 0));
    const eclipse::ReportSteps& steps = *model.report_steps;
    if (step >= steps.step_count())
        throw std::invalid_argument("--time-step " + std::to_string(step) + ": expected a report step 0.." +
                                    std::to_string(steps.step_count() - 1) + " of " + steps.file().string() + " (" +
                                    std::to_string(steps.step_count()) + " steps)");
    eclipse::hold_report_step(model.grid, steps, restart_array(model, property), step);
}

std::string step_caption(const LoadedModel& model, const std::string& property, int time_step) {
    const std::size_t steps = model.grid.step_count(property);
    if (time_step < 0 || steps == 0) return {};
    const auto& restart = model.report_steps ? model.report_steps : model.block_wells_restart;
    const std::string date = restart ? eclipse::date_at(restart->steps(), time_step) : std::string();
    return eclipse::step_caption(property, date, time_step, steps);
}

grid::GridDims model_dims(const std::vector<std::string>& model, std::size_t memory_limit_bytes) {
    if (const auto files = simulator_case(model)) return eclipse::read_egrid_dims(files->egrid);
    if (is_preset(model)) return preset_parameters(model).dims;
    return grid::read_grdecl_dims(files_of(model), read_options(memory_limit_bytes, {}));
}

LoadedModel load_block(const std::vector<std::string>& model, const grid::IjkBox& box, std::size_t memory_limit_bytes,
                       const std::string& property, int time_step, const std::vector<io::NamedFile>& outputs) {
    const auto started = std::chrono::steady_clock::now();
    LoadedModel loaded;
    if (const auto files = simulator_case(model)) {
        LoadedModel whole = load_case(*files, memory_limit_bytes, property);
        hold_property(whole, property, time_step, memory_limit_bytes);
        loaded.grid = grid::extract_box(whole.grid, box);
        const grid::GridDims& dims = whole.grid.dims();
        for (const std::string& name : whole.grid.property_names())
            loaded.grid.set_property(name, grid::box_values(*whole.grid.property(name), dims, box));
        for (const std::string& name : whole.grid.int_property_names())
            loaded.grid.set_int_property(name, grid::box_values(*whole.grid.int_property(name), dims, box));
        for (const std::string& name : whole.grid.dynamic_property_names()) {
            const std::size_t steps = whole.grid.step_count(name);
            loaded.grid.declare_dynamic_steps(name, steps);
            for (std::size_t step = 0; step < steps; ++step)
                if (const std::vector<float>* values = whole.grid.dynamic_property(name, step))
                    loaded.grid.set_dynamic_step(name, step, grid::box_values(*values, dims, box));
        }
        // No report_steps: they spread values over the whole grid's cells, not the box's.
        loaded.block_wells_restart = whole.report_steps;
        loaded.description = whole.description + " (box cut from the whole grid)";
    } else if (is_preset(model)) {
        const generators::GeneratorParameters parameters = preset_parameters(model);
        if (property == generators::generated_dynamic_property)
            throw std::invalid_argument("--property " + property + ": a preset's " + property +
                                        " steps need the whole model's water flood, which a rank generating its block "
                                        "alone cannot compute (write the model with `cutaway generate` and render the file)");
        generators::ProgressLog quiet(nullptr);
        loaded.grid = generators::generate_block(parameters, box, quiet, memory_limit_bytes).grid;
        loaded.description = model.front() + " (seed " + std::to_string(parameters.seed) + ", generated by block, no " +
                             generators::generated_dynamic_property + " steps)";
    } else {
        grid::GrdeclReadOptions options = read_options(memory_limit_bytes, outputs);
        options.block = box;
        loaded.grid = grid::load_grdecl(files_of(model), options, &loaded.warnings);
        loaded.description = files_description(model) + " (read by block)";
    }
    loaded.load_seconds = seconds_since(started);
    return loaded;
}

}  // namespace cutaway::app

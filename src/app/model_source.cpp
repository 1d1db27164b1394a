#include "app/model_source.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "generators/generator.h"
#include "generators/presets.h"
#include "grid/grdecl_reader.h"

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
    if (is_preset(model)) {
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

grid::GridDims model_dims(const std::vector<std::string>& model, std::size_t memory_limit_bytes) {
    if (is_preset(model)) return preset_parameters(model).dims;
    return grid::read_grdecl_dims(files_of(model), read_options(memory_limit_bytes, {}));
}

LoadedModel load_block(const std::vector<std::string>& model, const grid::IjkBox& box, std::size_t memory_limit_bytes,
                       const std::string& property, const std::vector<io::NamedFile>& outputs) {
    const auto started = std::chrono::steady_clock::now();
    LoadedModel loaded;
    if (is_preset(model)) {
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

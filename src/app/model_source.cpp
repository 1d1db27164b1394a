#include "app/model_source.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "generators/generator.h"
#include "generators/presets.h"
#include "grid/grdecl_reader.h"

namespace cutaway::app {

LoadedModel load_model(const std::vector<std::string>& model, std::size_t memory_limit_bytes,
                       const std::optional<std::string>& only_property) {
    const auto started = std::chrono::steady_clock::now();
    LoadedModel loaded;
    const std::string prefix = "preset:";
    if (model.empty()) throw std::invalid_argument("no model given: expected a GRDECL file or preset:NAME");
    if (model.front().rfind(prefix, 0) == 0) {
        if (model.size() > 1) throw std::invalid_argument(model.front() + ": a preset takes no further files");
        const std::string name = model.front().substr(prefix.size());
        const auto& known = generators::presets();
        const auto preset = std::find_if(known.begin(), known.end(), [&](const auto& p) { return p.name == name; });
        if (preset == known.end())
            throw std::invalid_argument(model.front() + ": expected preset:NAME with NAME one of " +
                                        generators::preset_names() + ", found '" + name + "'");
        generators::GeneratorParameters parameters = *preset;
        const bool without_flood = only_property && *only_property != generators::generated_dynamic_property;
        if (without_flood) parameters.time_steps = 0;
        generators::ProgressLog quiet(nullptr);
        loaded.grid = generators::generate_model(parameters, quiet, memory_limit_bytes).grid;
        loaded.description = model.front() + " (seed " + std::to_string(parameters.seed) +
                             (without_flood ? ", no " + generators::generated_dynamic_property + " steps: not asked for" : "") + ")";
    } else {
        grid::GrdeclReadOptions options;
        options.memory_limit_bytes = memory_limit_bytes;
        loaded.grid = grid::load_grdecl(std::vector<std::filesystem::path>(model.begin(), model.end()), options, nullptr);
        for (const std::string& file : model) loaded.description += (loaded.description.empty() ? "" : " + ") + file;
    }
    loaded.load_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return loaded;
}

}  // namespace cutaway::app

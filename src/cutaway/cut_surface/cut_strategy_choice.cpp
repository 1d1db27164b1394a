#include "cutaway/cut_surface/cut_strategy_choice.h"

#include "cutaway/cut_surface/cut_surface_registry.h"

namespace cutaway::pipeline {

bool is_software_rasteriser(std::string_view gl_renderer) {
    for (const std::string_view name : {"llvmpipe", "softpipe", "SwiftShader"})
        if (gl_renderer.find(name) != std::string_view::npos) return true;
    return false;
}

std::uint64_t auto_sweep_from_primaries(std::string_view gl_renderer) {
    return is_software_rasteriser(gl_renderer) ? auto_sweep_from_primaries_on_cpu : auto_sweep_from_primaries_on_gpu;
}

std::string resolve_cut_strategy(const std::string& name, std::uint64_t primaries, std::uint64_t sweep_from) {
    if (name != auto_cut_strategy) return name;
    return primaries < sweep_from ? "frustum-clusters" : "frustum-sweep";
}

std::string auto_choice_rule(std::uint64_t sweep_from) {
    return "auto: frustum-clusters below " + std::to_string(sweep_from) +
           " primary cells, frustum-sweep from there (the crossover on this kind of GL device, cut_strategy_choice.h)";
}

std::vector<std::string> cut_strategy_names() {
    std::vector<std::string> names{auto_cut_strategy};
    for (const CutSurfaceEntry& entry : cut_surface_strategies()) names.push_back(entry.name);
    return names;
}

}  // namespace cutaway::pipeline

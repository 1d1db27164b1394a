#include "cutaway/cut_surface/cut_strategy_choice.h"

#include "cutaway/cut_surface/cut_surface_registry.h"

namespace cutaway::pipeline {

std::string resolve_cut_strategy(const std::string& name, std::uint64_t primaries) {
    if (name != auto_cut_strategy) return name;
    return primaries < auto_sweep_from_primaries ? "frustum-clusters" : "frustum-sweep";
}

std::vector<std::string> cut_strategy_names() {
    std::vector<std::string> names{auto_cut_strategy};
    for (const CutSurfaceEntry& entry : cut_surface_strategies()) names.push_back(entry.name);
    return names;
}

}  // namespace cutaway::pipeline

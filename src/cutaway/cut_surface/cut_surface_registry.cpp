#include "cutaway/cut_surface/cut_surface_registry.h"

#include <stdexcept>

#include "cutaway/cut_surface/cone_field_strategy.h"
#include "cutaway/cut_surface/frustum_union.h"

namespace cutaway::pipeline {

std::vector<CutSurfaceEntry> cut_surface_strategies() {
    return {
        frustum_union_entry(),
        frustum_clusters_entry(),
        frustum_sweep_entry(),
        chamfer_3x3_entry(),
        chamfer_34_entry(),
        chamfer_5x5_entry(),
        jfa_entry(),
        jfa_plus_1_entry(),
        jfa_plus_2_entry(),
        one_plus_jfa_entry(),
        jfa_squared_entry(),
        exact_entry(),
    };
}

CutSurfaceEntry find_cut_surface(const std::string& name) {
    std::string known;
    for (CutSurfaceEntry& entry : cut_surface_strategies()) {
        if (entry.name == name) return entry;
        known += (known.empty() ? "" : ", ") + entry.name;
    }
    throw std::invalid_argument("cut-surface strategy '" + name + "': expected auto or one of " + known);
}

}  // namespace cutaway::pipeline

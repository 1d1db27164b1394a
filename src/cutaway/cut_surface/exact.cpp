// The exact cone field (max over every seed, with exact pruning, multithreaded) on the CPU: the
// reference the other strategies are measured against (--exact-check), usable as a strategy.
#include "cone_field/exact_reference.h"
#include "cutaway/cut_surface/cone_field_strategy.h"

namespace cutaway::pipeline {

cone_field::FloatImage exact_cone_cut(const cone_field::SeedImage& seeds, double slope_per_pixel) {
    return cone_field::exact_reference_cut(seeds, slope_per_pixel).cut;
}

CutSurfaceEntry exact_entry() {
    return cone_field_entry("exact", "the reference: exact max over all seeds with exact pruning, multithreaded on the CPU",
                            exact_cone_cut);
}

}  // namespace cutaway::pipeline

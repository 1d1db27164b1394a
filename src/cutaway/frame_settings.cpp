#include "cutaway/frame_settings.h"

namespace cutaway::pipeline {

const char* to_string(BorderMode mode) { return mode == BorderMode::raycast ? "raycast" : "threshold"; }
const char* to_string(MeanFilterKernel kernel) {
    switch (kernel) {
        case MeanFilterKernel::sampled: return "sampled";
        case MeanFilterKernel::distance_scaled: return "distance-scaled";
        default: return "full";
    }
}
const char* to_string(SeedSource seeds) { return seeds == SeedSource::boxes ? "boxes" : "geometry"; }
const char* to_string(DrawMode draw) { return draw == DrawMode::visible ? "visible" : "all-faces"; }
const char* to_string(Stage2Passes passes) {
    return passes == Stage2Passes::deferred ? "deferred" : passes == Stage2Passes::two ? "2" : "1";
}
const char* to_string(OnlyLayer only) {
    switch (only) {
        case OnlyLayer::primaries: return "primaries";
        case OnlyLayer::secondaries: return "secondaries";
        default: return "both";
    }
}

}  // namespace cutaway::pipeline

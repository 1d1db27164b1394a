#include "cutaway/cut_surface/jump_flood_split.h"

#include <algorithm>

namespace cutaway::pipeline {
namespace {

/// One axis of `extent` pixels: `pairs` pair starts (from 0) and the pixels [single_begin,
/// single_end) whose partner a step further lies outside the image. Whole spans of 2 x step pair
/// all their pixels; in the last, partial span the first pixels pair as far as partners exist.
struct AxisSplit {
    int pairs, single_begin, single_end;
};

AxisSplit split_axis(int extent, int step) {
    const int whole_spans = extent / (2 * step) * (2 * step);
    return {whole_spans / 2 + std::max(0, extent - step - whole_spans), std::max(whole_spans, extent - step),
            std::min(whole_spans + step, extent)};
}

}  // namespace

std::vector<JumpFloodRegion> jump_flood_regions(int width, int height, int step) {
    const AxisSplit x = split_axis(width, step), y = split_axis(height, step);
    std::vector<JumpFloodRegion> regions;
    for (const bool paired_y : {true, false})
        for (const bool paired_x : {true, false}) {
            const glm::ivec2 invocations(paired_x ? x.pairs : x.single_end - x.single_begin,
                                         paired_y ? y.pairs : y.single_end - y.single_begin);
            if (invocations.x <= 0 || invocations.y <= 0) continue;
            regions.push_back({paired_x, paired_y, {paired_x ? 0 : x.single_begin, paired_y ? 0 : y.single_begin}, invocations});
        }
    return regions;
}

}  // namespace cutaway::pipeline

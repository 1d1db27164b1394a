#include "cutaway/cut_surface/jump_flood_split.h"

#include <algorithm>

namespace cutaway::pipeline {
namespace {

/// `extent` rows: `pairs` pair starts (from 0) and the rows [single_begin,
/// single_end) whose partner a step further lies outside the image. Whole spans of 2 x step pair
/// all their rows; in the last, partial span the first rows pair as far as partners exist.
struct RowSplit {
    int pairs, single_begin, single_end;
};

RowSplit split_rows(int extent, int step) {
    const int whole_spans = extent / (2 * step) * (2 * step);
    return {whole_spans / 2 + std::max(0, extent - step - whole_spans), std::max(whole_spans, extent - step),
            std::min(whole_spans + step, extent)};
}

}  // namespace

std::vector<JumpFloodRegion> jump_flood_regions(int columns, int rows, int step) {
    const RowSplit y = split_rows(rows, step);
    std::vector<JumpFloodRegion> regions;
    if (columns <= 0) return regions;
    if (y.pairs > 0) regions.push_back({true, {0, 0}, {columns, y.pairs}});
    if (y.single_end > y.single_begin) regions.push_back({false, {0, y.single_begin}, {columns, y.single_end - y.single_begin}});
    return regions;
}

}  // namespace cutaway::pipeline

#include "volume/volume_cube.h"

#include <algorithm>
#include <limits>

namespace cutaway::volume {

const char* sorting_name(TraceSorting sorting) {
    switch (sorting) {
        case TraceSorting::inline_major: return "inline";
        case TraceSorting::crossline_major: return "crossline";
        case TraceSorting::single_trace: return "single trace";
        case TraceSorting::unsorted: return "unsorted";
    }
    return "unknown";
}

ValueRange present_value_range(const VolumeCube& cube) {
    float lo = std::numeric_limits<float>::max(), hi = std::numeric_limits<float>::lowest();
    const std::size_t traces = std::size_t(cube.dims.inlines) * std::size_t(cube.dims.crosslines);
    const std::size_t ns = std::size_t(cube.dims.samples);
    for (std::size_t trace = 0; trace < traces; ++trace) {
        if (!cube.trace_present.empty() && !cube.trace_present[trace]) continue;
        const auto [mn, mx] = std::minmax_element(cube.samples.begin() + std::ptrdiff_t(trace * ns),
                                                  cube.samples.begin() + std::ptrdiff_t((trace + 1) * ns));
        lo = std::min(lo, *mn);
        hi = std::max(hi, *mx);
    }
    if (lo > hi) return {cube.null_value, cube.null_value};
    return {lo, hi};
}

}  // namespace cutaway::volume

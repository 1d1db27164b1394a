#include "volume/quantised_volume.h"

#include <algorithm>
#include <cmath>

namespace cutaway::volume {

std::uint8_t quantise_value(float value, ValueRange range) {
    if (!(range.max > range.min)) return 0;
    const double scaled = 255.0 * (double(value) - range.min) / (double(range.max) - range.min);
    return std::uint8_t(std::clamp(std::lround(scaled), 0L, 255L));
}

QuantisedVolume quantise(const VolumeCube& cube) {
    QuantisedVolume volume;
    volume.dims = cube.dims;
    volume.range = present_value_range(cube);
    volume.axes.time_ms = {0, double(std::max(0, cube.dims.samples - 1)) * cube.sample_interval_ms};
    if (!cube.crossline_numbers.empty()) volume.axes.crossline = {double(cube.crossline_numbers.front()), double(cube.crossline_numbers.back())};
    if (!cube.inline_numbers.empty()) volume.axes.inline_number = {double(cube.inline_numbers.front()), double(cube.inline_numbers.back())};
    volume.levels.resize(cube.samples.size());
    std::transform(cube.samples.begin(), cube.samples.end(), volume.levels.begin(),
                   [range = volume.range](float value) { return quantise_value(value, range); });
    return volume;
}

}  // namespace cutaway::volume

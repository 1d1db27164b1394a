#pragma once
// The cube's samples divided into 256 levels (the paper's quantisation), as uploaded to the GPU.
#include <cstdint>
#include <vector>

#include "volume/volume_cube.h"

namespace cutaway::volume {

/// What each voxel axis spans in the survey's own numbers, for the axes' tick values: time in
/// milliseconds (from 0), crossline and inline numbers. first == last: unknown (voxel indices).
struct SurveySpan {
    double first = 0, last = 0;
};
struct SurveyAxes {
    SurveySpan time_ms, crossline, inline_number;  ///< in voxel-axis order (time fastest)
};

/// Levels 0..255 in the VolumeCube layout: (inline i, crossline x, time t) at
/// `levels[(i * crosslines + x) * samples + t]`, so t is the fastest (texture width) axis.
struct QuantisedVolume {
    CubeDims dims;
    std::vector<std::uint8_t> levels;
    ValueRange range;  ///< sample value of level 0 (min) and of level 255 (max)
    SurveyAxes axes;   ///< the cube's survey numbers (quantise copies them)
};

/// Level of `value`: round(255 (value - min) / (max - min)), clamped to 0..255; 0 when min == max.
std::uint8_t quantise_value(float value, ValueRange range);

/// Levels over the range of the traces present (missing traces' nulls clamp into it).
QuantisedVolume quantise(const VolumeCube& cube);

}  // namespace cutaway::volume

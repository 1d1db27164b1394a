#pragma once
// Colouring values at 16 bits (2 bytes per active cell instead of 4): each value as an unsigned
// normalised code over the span of the values given, decoded by the shaders as
// offset + span x code / 65535 (common/grid.glsl cell_value). For values that only colour: the
// decoded value is within span / 131070 of the value given, invisible in a 256-texel colour map,
// but a range selection over it would not be exact (CutawayRenderer refuses one). No OpenGL.
#include <cstdint>
#include <span>
#include <vector>

namespace cutaway::pipeline {

struct QuantisedValues {
    std::vector<std::uint16_t> codes;
    float offset = 0;  ///< the smallest finite value (decoded from code 0)
    float span = 0;    ///< largest minus smallest finite value (code 65535 decodes to offset + span)
};

/// `values` quantised over their finite range; a non-finite value gets code 0.
QuantisedValues quantise_unorm16(std::span<const float> values);

}  // namespace cutaway::pipeline

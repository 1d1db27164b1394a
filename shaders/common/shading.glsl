// Cell colours and lighting shared by every pass that draws faces.
uniform sampler1D colour_map;   // perceptual map, 256 texels
uniform vec2 value_range;       // property values mapped to the ends of the colour map
uniform bool log_scale;         // map log10 of the values (value_range above 0; values below it clamp)

vec3 cell_colour(uint compact_cell) {
    float value = cell_value(compact_cell);
    vec2 range = value_range;
    if (log_scale) {
        range = log2(value_range);  // log2: the ratio to the range is the same as log10's
        value = log2(max(value, value_range.x));
    }
    float span = range.y - range.x;
    float t = span > 0.0 ? (value - range.x) / span : 0.5;
    return texture(colour_map, clamp(t, 0.0, 1.0)).rgb;
}

#include "common/lighting.glsl"

#include "common/line_style.glsl"

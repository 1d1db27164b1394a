#version 450 core
// Mean filter of the cut surface (normal and depth) over a KERNEL x KERNEL window, removing the
// staircase between frustums. SAMPLED fetches every other texel in each direction (about a
// quarter of the texels) instead of all of them. Positions are rebuilt from the filtered depth.
#include "cut_surface/cut_output.glsl"

uniform sampler2D cut_input;

#ifdef SAMPLED
const int stride = 2;
#else
const int stride = 1;
#endif
const int radius = KERNEL / 2;

void main() {
    ivec2 centre = ivec2(gl_FragCoord.xy);
    ivec2 last = ivec2(cut_size) - 1;
    vec4 sum = vec4(0.0);
    float count = 0.0;
    for (int dy = -radius; dy <= radius; dy += stride)
        for (int dx = -radius; dx <= radius; dx += stride) {
            sum += texelFetch(cut_input, clamp(centre + ivec2(dx, dy), ivec2(0), last), 0);
            count += 1.0;
        }
    vec4 mean = sum / count;
    vec3 world = cut_world_position(gl_FragCoord.xy, mean.a);
    vec3 normal = dot(mean.rgb, mean.rgb) > 0.0 ? normalize(mean.rgb) : vec3(0.0, 0.0, 1.0);
    out_cut = vec4(normal, mean.a);
    out_position = vec4(world, 1.0);
}

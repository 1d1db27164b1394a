#version 450 core
// Pass 2 of the paper: front faces only give the entry point; march to the exit point of pass 1 at
// `step_length` voxels, sample trilinearly, classify with the table and composite front to back:
//   C_out a_out = C_in a_in + C_now a_now (1 - a_in),  a_out = a_in + a_now (1 - a_in).
// Variants (defined or not): OPACITY_CORRECTION, JITTER, EARLY_TERMINATION, EMPTY_SPACE_SKIPPING.
#include "volume/ray_common.glsl"

in vec3 voxel_position;

layout(binding = 0) uniform sampler2D exit_points;
layout(binding = 1) uniform sampler3D volume_levels;    // R8, linear filtering: level / 255
layout(binding = 2) uniform sampler1D transfer_table;   // 256 RGBA32F, straight colour, alpha per voxel step
layout(binding = 3) uniform usampler3D occupied_blocks; // R8UI per block, 1 = something visible
uniform vec3 box;
uniform float step_length;
uniform float early_termination_alpha;
uniform vec4 background;
uniform float block_size;

layout(location = 0) out vec4 colour;
layout(location = 1) out uvec2 counts;  // (samples taken, 1 for a ray that hit the cube)

void main() {
    vec4 exit_point = texelFetch(exit_points, ivec2(gl_FragCoord.xy), 0);
    vec3 entry = voxel_position;
    vec3 span = exit_point.xyz - entry;
    float len = exit_point.w > 0.0 ? length(span) : 0.0;
    vec4 acc = vec4(0.0);
    uint samples = 0u;
    if (len > 0.0) {
        vec3 dir = span / len;
#ifdef JITTER
        float start = jitter_fraction(uvec2(gl_FragCoord.xy)) * step_length;
#else
        float start = 0.0;
#endif
#ifdef EMPTY_SPACE_SKIPPING
        ivec3 last_block = textureSize(occupied_blocks, 0) - 1;
#endif
        for (int i = 0;;) {
            float t = start + float(i) * step_length;
            if (t >= len) break;
            vec3 p = entry + dir * t;
#ifdef EMPTY_SPACE_SKIPPING
            ivec3 block = clamp(ivec3(floor(p / block_size)), ivec3(0), last_block);
            if (texelFetch(occupied_blocks, block, 0).r == 0u) {
                i += max(1, int(ceil(block_exit_distance(p, dir, block, block_size) / step_length)));
                continue;
            }
#endif
            vec4 c = lookup_table(transfer_table, texture(volume_levels, p / box).r * 255.0);
#ifdef OPACITY_CORRECTION
            float a = 1.0 - pow(1.0 - c.a, step_length);
#else
            float a = c.a;
#endif
            float weight = (1.0 - acc.a) * a;
            acc.rgb += weight * c.rgb;
            acc.a += weight;
            ++samples;
            ++i;
#ifdef EARLY_TERMINATION
            if (acc.a >= early_termination_alpha) break;
#endif
        }
    }
    colour = vec4(acc.rgb + (1.0 - acc.a) * background.rgb, 1.0);
    counts = uvec2(samples, exit_point.w > 0.0 ? 1u : 0u);
}

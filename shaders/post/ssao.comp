#version 450 core
// Screen-space ambient occlusion in the style of Shanmugam & Arikan 2007: SAMPLES points in a
// disc of world radius `radius` around each pixel, rebuilt from linear depth; each occludes by
// how much it lies above the pixel's tangent plane, with distance falloff. Works on every
// surface of the frame, the cut fill included (its normals are the cut surface's). A compute pass
// with image loads: on llvmpipe at 1920x1080 faster than the fragment pass with texelFetch
// (sapphire, alternating runs; the same image), still so once the spiral turned by a rotation
// instead of a sine and cosine per sample and the divisions per sample became multiplies (the
// loads are then much of what remains).
// HALF_RESOLUTION: one invocation per 2x2 block, shading the block's even pixel (2t) with the same
// full-resolution samples, and storing that pixel's depth beside the factor for the composite's
// depth-aware upsampling (post/composite.comp, ambient_at): a quarter of the work.
// CUT_DEPTH (the cut was made from the model camera): where a pixel shows the cut surface
// (flag_shows_cut) the depth stored there is its cell's far face, behind the cut; the cut's own
// depth at the pixel stands in, so a wall cut through thin layers is one surface, not a sawtooth
// of far faces that darkened into a lattice (fig. 11's rear wall). The stored depth stays the
// face's: the border test, the MPI compositing and the identity tests read it.
layout(local_size_x = 64, local_size_y = 16) in;  // gl::dispatch_over says why
#include "common/shared_constants.h"

#include "common/packed_normal.glsl"

layout(rg32ui, binding = img_scene_normal_depth) uniform readonly uimage2D normal_depth;  // eye-space normal, linear depth (0 = background; packed_normal.glsl)
layout(rg32f, binding = img_post_ambient) uniform writeonly image2D ambient;        // factor, linear depth of its pixel
uniform vec2 projection_scale;   // P[0][0], P[1][1]
uniform vec2 viewport_size;
uniform float radius;            // render units
uniform float strength;
uniform float min_factor;        // the least factor: occluded pixels stay dark, never black
#ifdef CUT_DEPTH
layout(rg32ui, binding = img_scene_id) uniform readonly uimage2D scene_id;          // compact cell + 1, pixel flags
layout(r32f, binding = img_post_cut_depth) uniform readonly image2D cut_depth;     // the resolved cut, the model camera's
// Outside the images both loads read 0: not on the cut, the stored depth (0 there too).
float depth_shown(ivec2 texel, float stored) {
    return (imageLoad(scene_id, texel).g & flag_shows_cut) != 0u ? imageLoad(cut_depth, texel).r : stored;
}
#else
float depth_shown(ivec2 texel, float stored) { return stored; }
#endif

// The eye-space point seen at window position `window` at linear depth `depth`, from the
// per-pixel factors ndc_per_px = 2 / (viewport_size * projection_scale) and ndc_origin =
// -1 / projection_scale (multiplies: a division per sample cost more than the load on llvmpipe).
vec3 eye_position(vec2 window, float depth, vec2 ndc_per_px, vec2 ndc_origin) {
    return vec3((window * ndc_per_px + ndc_origin) * depth, -depth);
}

void main() {
    ivec2 target = ivec2(gl_GlobalInvocationID.xy);  // texel of `ambient`
#ifdef HALF_RESOLUTION
    ivec2 pixel = 2 * target;
#else
    ivec2 pixel = target;
#endif
    if (any(greaterThanEqual(pixel, ivec2(viewport_size)))) return;
    vec2 window = vec2(pixel) + 0.5;  // the pixel's centre, as gl_FragCoord.xy
    uvec2 here = imageLoad(normal_depth, pixel).rg;
    float here_depth = depth_shown(pixel, packed_value(here));
    if (here_depth <= 0.0) {  // background: a branch, so that background-only SIMD lanes skip the samples
        imageStore(ambient, target, vec4(1.0, 0.0, 0.0, 0.0));
        return;
    }
    vec2 ndc_per_px = 2.0 / (viewport_size * projection_scale);
    vec2 ndc_origin = -1.0 / projection_scale;
    vec3 position = eye_position(window, here_depth, ndc_per_px, ndc_origin);
    vec3 normal = packed_normal(here);
    float radius_px = radius * projection_scale.y * 0.5 * viewport_size.y / here_depth;
    // Per-pixel rotation of a fixed spiral (interleaved gradient noise) hides banding.
    float angle0 = 6.2831853 * fract(52.9829189 * fract(dot(window, vec2(0.06711056, 0.00583715))));
    // The spiral's direction turns by the golden angle per sample: a 2x2 rotation, not a sine and
    // cosine per sample.
    vec2 direction = vec2(cos(angle0), sin(angle0));
    const vec2 golden_turn = vec2(cos(2.3999632), sin(2.3999632));
    float inverse_radius2 = 1.0 / (radius * radius);
    float occlusion = 0.0;
    for (int k = 0; k < SAMPLES; ++k) {
        float t = (float(k) + 0.5) / float(SAMPLES);
        vec2 offset = radius_px * sqrt(t) * direction;
        direction = vec2(direction.x * golden_turn.x - direction.y * golden_turn.y,
                         direction.x * golden_turn.y + direction.y * golden_turn.x);
        ivec2 texel = ivec2(window + offset);
        // Outside the image a load reads 0: no depth, no occlusion (selects, not branches).
        float depth = depth_shown(texel, packed_value(imageLoad(normal_depth, texel).rg));
        vec3 d = eye_position(vec2(texel) + 0.5, depth, ndc_per_px, ndc_origin) - position;
        float distance2 = dot(d, d);
        float occludes = max(dot(normal, d) * inversesqrt(distance2 + 1e-12) - 0.05, 0.0) / (1.0 + distance2 * inverse_radius2);
        occlusion += depth > 0.0 ? occludes : 0.0;
    }
    imageStore(ambient, target, vec4(clamp(1.0 - strength * occlusion / float(SAMPLES), min_factor, 1.0), here_depth, 0.0, 0.0));
}

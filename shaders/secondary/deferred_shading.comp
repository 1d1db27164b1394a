#version 450 core
// Stage 2, deferred shading (the visible path's default, --stage2-passes deferred): the draw
// (secondary/secondary.frag, DEFERRED) made only the cut test, leaving at each pixel the nearest
// kept fragment's cell, face info, edge line, face normal and linear depth; this pass shades each visible
// secondary pixel once (common/secondary_shading.glsl) and, with BORDER_RAYCAST, runs the ray-cast
// border test on it, writing colour, eye normal + linear depth and the pixel flags. On llvmpipe a
// fragment shader runs its lighting for every fragment drawn (a discard only masks lanes): at
// petra's default camera stage 2 draws 8 fragments per pixel, most of them in front of the cut.
// Variants: BORDER_RAYCAST or BORDER_THRESHOLD, HIDE_INTERNAL_LINES, CUT_CAMERA_IS_VIEW (the cut was
// made from the model camera: a pixel's cut sample is its own pixel), VIEW_REAR_SHELL (freeze view).
layout(local_size_x = 64, local_size_y = 4) in;
#include "common/grid.glsl"
#include "common/shading.glsl"
#include "common/cut_lookup.glsl"
#include "common/shared_constants.h"
#include "common/secondary_shading.glsl"
#include "common/deferred_face.glsl"
#include "common/packed_normal.glsl"

layout(rgba8, binding = img_scene_colour) uniform writeonly image2D scene_colour;
layout(rg32ui, binding = img_scene_id) uniform uimage2D scene_id;                 // compact cell + 1 (0: background), deferred face
layout(rg32ui, binding = img_scene_face_plane) uniform readonly uimage2D face_plane;      // world face normal, linear depth (DEFERRED; packed_normal.glsl)
layout(rg32ui, binding = img_scene_normal_depth) uniform writeonly uimage2D normal_depth;  // eye normal, linear depth (packed_normal.glsl)

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, ivec2(viewport_size)))) return;
    uvec2 id = imageLoad(scene_id, texel).rg;
    if (id.x == 0u) return;  // background (cleared): nothing drawn
    uvec2 plane = imageLoad(face_plane, texel).rg;
    vec3 plane_normal = packed_normal(plane);
    float linear_depth = packed_value(plane);  // the fragment's, as the one-pass draw stores it (not rebuilt from the depth buffer)
    vec2 window = vec2(texel) + 0.5;  // the pixel's centre, as gl_FragCoord.xy
    vec2 ndc = window / viewport_size * 2.0 - 1.0;
    vec3 world = (inverse_view * vec4(ndc / projection_scale * linear_depth, -linear_depth, 1.0)).xyz;
#ifdef CUT_CAMERA_IS_VIEW
    CutSample here = cut_at_texel(texel, linear_depth, true);
#else
    CutSample here = cut_at(world);
#endif
    uint face_info = deferred_face_info(id.y);
    SecondaryShade s = shade_secondary(here, world, texel, id.x - 1u, face_info, plane_normal,
                                       deferred_edge_opacity(id.y), deferred_edge_line(id.y));
#ifdef BORDER_RAYCAST
    bool hide_internal_lines = false;
#ifdef HIDE_INTERNAL_LINES
    hide_internal_lines = true;
#endif
    if (raycast_border_at(window, texel, world, plane_normal))
        colour_border(s.colour, s.flags, face_info & 3u, hide_internal_lines, id.x - 1u, stored_eye_normal(s.normal));
#endif
    imageStore(scene_colour, texel, vec4(s.colour, 1.0));
    imageStore(normal_depth, texel, uvec4(pack_normal_and(normalize(mat3(model_view) * s.normal), linear_depth), 0u, 0u));
    imageStore(scene_id, texel, uvec4(id.x, s.flags, 0u, 0u));
}

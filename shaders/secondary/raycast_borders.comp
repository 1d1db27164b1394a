#version 450 core
// Stage 2, ray-cast borders: the paper's test once per visible secondary pixel (the face plane
// and depth were written by secondary.frag), instead of for every fragment drawn. Border pixels
// are recoloured and flagged in place (image load/store: each pixel touches only itself). A compute
// pass: on llvmpipe a full-screen triangle into a framebuffer without attachments had a large
// cost at 1080p before its shader did anything.
layout(local_size_x = 64, local_size_y = 4) in;
#include "common/grid.glsl"
#include "common/shading.glsl"
#include "common/cut_lookup.glsl"
#include "common/shared_constants.h"
#include "common/secondary_shading.glsl"
#include "common/packed_normal.glsl"

layout(rg32ui, binding = img_scene_face_plane) uniform readonly uimage2D face_plane;    // world face normal, 1 + face class (0: a primary; not cleared where id is 0)
layout(rg32ui, binding = img_scene_normal_depth) uniform readonly uimage2D normal_depth;  // eye normal, linear depth in the model camera
uniform bool hide_internal_lines;  // no border lines on the cut fill (shell-cut lines stay)
layout(rgba8, binding = img_scene_colour) uniform image2D scene_colour;
layout(rg32ui, binding = img_scene_id) uniform uimage2D scene_id;

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, ivec2(viewport_size)))) return;
    vec2 window = vec2(texel) + 0.5;  // the pixel's centre, as gl_FragCoord.xy
    uvec2 id = imageLoad(scene_id, texel).rg;
    if (id.x == 0u) return;  // background: face_plane is not cleared (frame_targets.h)
    uvec2 plane = imageLoad(face_plane, texel).rg;
    float face_class_plus_1 = packed_value(plane);
    if (face_class_plus_1 == 0.0) return;
    uvec2 eye_normal_depth = imageLoad(normal_depth, texel).rg;
    float depth = packed_value(eye_normal_depth);
    vec2 ndc = window / viewport_size * 2.0 - 1.0;
    vec3 world = (inverse_view * vec4(ndc / projection_scale * depth, -depth, 1.0)).xyz;
    if (!raycast_border_at(window, texel, world, packed_normal(plane))) return;
    vec3 unlined = imageLoad(scene_colour, texel).rgb;
    vec3 colour = unlined;
    uint flags = id.y;
    colour_border(colour, flags, uint(face_class_plus_1 + 0.5) - 1u, hide_internal_lines, id.x - 1u,
                  packed_normal(eye_normal_depth));
    if (flags == id.y && colour == unlined) return;  // a faded line changes the colour alone
    imageStore(scene_colour, texel, vec4(colour, 1.0));
    imageStore(scene_id, texel, uvec4(id.x, flags, 0u, 0u));
}

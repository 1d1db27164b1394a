#version 450 core
// Stage 2, ray-cast borders: the paper's test once per visible secondary pixel (the face plane
// and depth were written by secondary.frag), instead of for every fragment drawn. Border pixels
// are recoloured and flagged in place (image load/store: each pixel touches only itself). A compute
// pass: on llvmpipe a full-screen triangle into a framebuffer without attachments cost 60 ms at
// 1080p before its shader did anything.
layout(local_size_x = 64, local_size_y = 4) in;
#include "common/cut_lookup.glsl"
#include "common/border_test.glsl"
#include "common/line_style.glsl"

layout(rgba32f, binding = 2) uniform readonly image2D face_plane;    // world face normal, w = 1 + face class (0: a primary; not cleared where id is 0)
layout(rgba32f, binding = 3) uniform readonly image2D normal_depth;  // w: linear depth in the model camera
uniform vec3 shell_cut_colour;
uniform bool hide_internal_lines;  // no border lines on the cut fill (shell-cut lines stay)
layout(rgba8, binding = 0) uniform image2D scene_colour;
layout(rg32ui, binding = 1) uniform uimage2D scene_id;

const uint face_class_shell = 3u;
const uint flag_cut_fill = 2u;
const uint flag_border = 4u;
const uint flag_shell_cut = 16u;

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, ivec2(viewport_size)))) return;
    vec2 window = vec2(texel) + 0.5;  // the pixel's centre, as gl_FragCoord.xy
    uvec2 id = imageLoad(scene_id, texel).rg;
    if (id.x == 0u) return;  // background: face_plane is not cleared (frame_targets.h)
    vec4 plane = imageLoad(face_plane, texel);
    if (plane.w == 0.0) return;
    float depth = imageLoad(normal_depth, texel).a;
    vec2 ndc = window / viewport_size * 2.0 - 1.0;
    vec3 world = (inverse_view * vec4(ndc / projection_scale * depth, -depth, 1.0)).xyz;
    if (at_view_rear_shell(world, texel) || !raycast_border(window, world, plane.xyz)) return;  // secondary.frag
    bool shell = uint(plane.w + 0.5) - 1u == face_class_shell;
    if (!shell && hide_internal_lines && (id.y & flag_cut_fill) != 0u) return;
    vec3 colour = shell ? shell_cut_colour : line_colour_on(imageLoad(scene_colour, texel).rgb);
    imageStore(scene_colour, texel, vec4(colour, 1.0));
    id.y |= shell ? (flag_border | flag_shell_cut) : flag_border;
    imageStore(scene_id, texel, uvec4(id, 0u, 0u));
}

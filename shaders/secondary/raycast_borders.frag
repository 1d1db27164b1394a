#version 450 core
// Stage 2, ray-cast borders: the paper's test once per visible secondary pixel (the face plane
// and depth were written by secondary.frag), instead of for every fragment drawn. Border pixels
// are recoloured and flagged in place (image load/store: each pixel touches only itself).
#include "common/cut_lookup.glsl"
#include "common/border_test.glsl"
#include "common/line_style.glsl"

uniform sampler2D face_plane;    // world face normal, w = 1 + face class (0: no secondary)
uniform sampler2D normal_depth;  // w: linear depth in the model camera
uniform mat4 inverse_view;       // model camera
uniform vec2 projection_scale;   // model camera P[0][0], P[1][1]
uniform vec3 shell_cut_colour;
uniform bool hide_internal_lines;  // no border lines on the cut fill (shell-cut lines stay)
layout(rgba8) uniform image2D scene_colour;
layout(rg32ui) uniform uimage2D scene_id;

const uint face_class_shell = 3u;
const uint flag_cut_fill = 2u;
const uint flag_border = 4u;
const uint flag_shell_cut = 16u;

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    vec4 plane = texelFetch(face_plane, texel, 0);
    if (plane.w == 0.0) return;
    float depth = texelFetch(normal_depth, texel, 0).a;
    vec2 ndc = gl_FragCoord.xy / viewport_size * 2.0 - 1.0;
    vec3 world = (inverse_view * vec4(ndc / projection_scale * depth, -depth, 1.0)).xyz;
    if (at_view_rear_shell(world, texel) || !raycast_border(gl_FragCoord.xy, world, plane.xyz)) return;  // secondary.frag
    bool shell = uint(plane.w + 0.5) - 1u == face_class_shell;
    uvec2 id = imageLoad(scene_id, texel).rg;
    if (!shell && hide_internal_lines && (id.y & flag_cut_fill) != 0u) return;
    vec3 colour = shell ? shell_cut_colour : line_colour_on(imageLoad(scene_colour, texel).rgb);
    imageStore(scene_colour, texel, vec4(colour, 1.0));
    id.y |= shell ? (flag_border | flag_shell_cut) : flag_border;
    imageStore(scene_id, texel, uvec4(id, 0u, 0u));
}

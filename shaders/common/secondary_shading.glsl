// Stage 2's shading of a kept secondary point, shared by secondary/secondary.frag (once per
// fragment drawn) and secondary/deferred_shading.comp (once per pixel, from what the DEFERRED
// pass left there), and the ray-cast border lines (secondary/raycast_borders.comp and the
// deferred pass). Needs common/grid.glsl, common/shading.glsl, common/cut_lookup.glsl and
// common/pixel_flags.glsl. Variants: BORDER_THRESHOLD (the naive border test, here),
// HIDE_INTERNAL_LINES (no cell edges on the cut fill).
#include "common/border_test.glsl"

uniform vec3 shell_cut_colour;
// focal_px: the model camera's focal length, pixels (common/cameras.glsl).

struct SecondaryShade {
    vec3 colour;
    vec3 normal;  // render space
    uint flags;   // common/pixel_flags.glsl
};

// The point `world` seen at model-camera pixel `pixel`, `here` its cut sample, on a face of
// `compact_cell` with `face_info` (common/face_varyings.glsl) and outward unit `face_normal`;
// `edge_opacity`: the cell edge line's there (common/line_style.glsl face_edge_opacity),
// `edge_line`: whether it counts as an edge pixel. Points seen from inside their cell take the
// cut surface's normal, so the cells the cut opens look solid.
SecondaryShade shade_secondary(CutSample here, vec3 world, ivec2 pixel, uint compact_cell, uint face_info,
                               vec3 face_normal, float edge_opacity, bool edge_line) {
    bool inside_view = (face_info & 4u) != 0u;
    SecondaryShade s;
    s.normal = face_normal;
    if (inside_view) {  // a branch: only cut fill rebuilds the cut's normal
        // Where the cut is clamped to the rear shell, a shell face seen from inside takes its own
        // plane: the cut's normal there follows the shell's triangles, a shade per triangle.
        bool rear_shell_face = here.cut_depth == 0.0 || ((face_info & 3u) == face_class_shell && cut_is_rear_shell(here.texel));
        s.normal = rear_shell_face ? -face_normal : cut_normal_at(here.texel);
    }
    s.colour = lit(cell_colour(compact_cell), s.normal, world);
    s.flags = inside_view ? flag_cut_fill : 0u;
    bool hide_lines = false;  // on the cut fill, with --hide-internal-lines
#ifdef HIDE_INTERNAL_LINES
    hide_lines = inside_view;
#endif
    if (hide_lines) edge_opacity = 0.0;
    s.colour = mix(s.colour, line_colour_on(s.colour), edge_opacity);
    if (edge_line && !hide_lines) s.flags |= flag_edge;
#ifdef BORDER_THRESHOLD
    // Naive: depth within epsilon of the cut, epsilon = the depth w pixels span at this distance.
    // Frozen view: no border lines on the model camera's rear shell (as on the cut's own clamp),
    // which the frozen cut may touch where the cut camera saw a primary in front of it.
    bool shell = (face_info & 3u) == face_class_shell;
    if (here.cut_depth > 0.0 && !cut_is_rear_shell(here.texel) && !at_view_rear_shell(world, pixel) &&
        (shell || !hide_lines) && here.fragment_depth - here.cut_depth < border_width * here.fragment_depth / focal_px) {
        s.colour = shell ? shell_cut_colour : line_colour_on(s.colour);
        s.flags |= shell ? (flag_border | flag_shell_cut) : flag_border;
    }
#endif
    return s;
}

// Whether the visible secondary pixel `pixel` (centre `window`), showing the point `world` on a
// face plane of normal `plane_normal`, lies within w of a border (the paper's ray-cast test,
// common/border_test.glsl); never on the model camera's rear shell (freeze view).
bool raycast_border_at(vec2 window, ivec2 pixel, vec3 world, vec3 plane_normal) {
    return !at_view_rear_shell(world, pixel) && raycast_border(window, world, plane_normal);
}

// A border pixel's colour and flags on a face of `face_class`: with `hide_internal_lines`, no
// line on the cut fill but where a shell face meets the cut.
void colour_border(inout vec3 colour, inout uint flags, uint face_class, bool hide_internal_lines) {
    bool shell = face_class == face_class_shell;
    if (!shell && hide_internal_lines && (flags & flag_cut_fill) != 0u) return;
    colour = shell ? shell_cut_colour : line_colour_on(colour);
    flags |= shell ? (flag_border | flag_shell_cut) : flag_border;
}

// Stage 2's shading of a kept secondary point, shared by secondary/secondary.frag (once per
// fragment drawn) and secondary/deferred_shading.comp (once per pixel, from what the DEFERRED
// pass left there), and the ray-cast border lines (secondary/raycast_borders.comp and the
// deferred pass). Needs common/grid.glsl, common/shading.glsl, common/cut_lookup.glsl and
// common/pixel_flags.glsl. Variants: BORDER_THRESHOLD (the naive border test, here),
// HIDE_INTERNAL_LINES (no cell edges on the cut fill).
#include "common/border_test.glsl"
#include "common/packed_normal.glsl"

uniform vec3 shell_cut_colour;
// focal_px: the model camera's focal length, pixels (common/cameras.glsl).

// Border lines on the cut fill (where the cut crosses cell faces) fade out where they would lie
// only a few pixels apart on screen: a wall cut through thin layers would otherwise carry lines
// closer together than their width, a mesh that reads as data. For each of the cell's three
// families of opposite faces (across I, J, K), the cut (eye-space unit normal `eye_normal`)
// crosses the two faces along lines a vector v apart within the cut: v is the shortest vector in
// the cut's plane that spans the cell's thickness across those faces. The spacing is v's length
// on screen at the cell's centre, the fade is over the closest family: full lines from 6 pixels
// apart, none below 3. A cut parallel to a family crosses none of its faces (the floor of an
// aperture-180 cut along the layers keeps the lines of the pillars' faces).
// The on-screen spacing of the cut's crossings of the two faces across `edge` (the cell's edge
// between them; `side_a`, `side_b`: its other two edges), from `centre` (eye space).
float crossing_spacing_px(vec3 edge, vec3 side_a, vec3 side_b, vec3 centre, vec3 eye_normal) {
    vec3 across = cross(side_a, side_b);  // the faces' normal
    if (dot(across, across) < 1e-20) return 1e30;  // a collapsed cell
    vec3 m = normalize(across);
    vec3 m_in_cut = m - dot(m, eye_normal) * eye_normal;
    float in_cut = dot(m_in_cut, m_in_cut);
    if (in_cut < 1e-6) return 1e30;  // the cut runs along these faces
    vec3 v = abs(dot(edge, m)) / in_cut * m_in_cut;
    vec3 a = centre - 0.5 * v, b = centre + 0.5 * v;
    return distance(a.xy * (focal_px / max(-a.z, near_plane)), b.xy * (focal_px / max(-b.z, near_plane)));
}

float cut_fill_line_opacity(uint compact_cell, vec3 eye_normal) {
    // Corner 0 and its neighbours along I, J, K (corner_position's corner bits): four corners,
    // not eight, as this runs for every border pixel of the cut fill; no arrays (indexed by a
    // loop counter they cost memory traffic on llvmpipe).
    vec3 origin = (model_view * vec4(corner_position(compact_cell, 0u), 1.0)).xyz;
    vec3 i = (model_view * vec4(corner_position(compact_cell, 1u), 1.0)).xyz - origin;
    vec3 j = (model_view * vec4(corner_position(compact_cell, 2u), 1.0)).xyz - origin;
    vec3 k = (model_view * vec4(corner_position(compact_cell, 4u), 1.0)).xyz - origin;
    vec3 centre = origin + 0.5 * (i + j + k);
    float spacing = min(crossing_spacing_px(i, j, k, centre, eye_normal),
                        min(crossing_spacing_px(j, k, i, centre, eye_normal), crossing_spacing_px(k, i, j, centre, eye_normal)));
    return smoothstep(3.0, 6.0, spacing);
}

// `normal` (render space) in eye space as the scene's normal_depth target holds it (quantised):
// every pass that fades the lines (fragment, deferred, border passes) sees the same normal.
vec3 stored_eye_normal(vec3 normal) { return unpack_unit_normal(pack_unit_normal(normalize(mat3(model_view) * normal))); }

// A border pixel's colour and flags on a face of `face_class` of `compact_cell`: with
// `hide_internal_lines`, no line on the cut fill but where a shell face meets the cut; on the cut
// fill, faded where the lines crowd (cut_fill_line_opacity; `eye_normal`: the cut's there).
void colour_border(inout vec3 colour, inout uint flags, uint face_class, bool hide_internal_lines, uint compact_cell,
                   vec3 eye_normal) {
    bool shell = face_class == face_class_shell;
    bool cut_fill = (flags & flag_cut_fill) != 0u;
    if (!shell && hide_internal_lines && cut_fill) return;
    float opacity = 1.0;
    if (!shell && cut_fill) opacity = cut_fill_line_opacity(compact_cell, eye_normal);
    if (opacity == 0.0) return;
    colour = shell ? shell_cut_colour : mix(colour, line_colour_on(colour), opacity);
    if (opacity > 0.5) flags |= shell ? (flag_border | flag_shell_cut) : flag_border;
}

struct SecondaryShade {
    vec3 colour;
    vec3 normal;  // render space
    uint flags;   // common/pixel_flags.glsl
};

// Whether a point seen from inside its cell (`inside_view`) shows the cut surface: not where the
// cut is clamped to the rear shell, there a shell face seen from inside is the surface shown.
bool shows_cut_surface(bool inside_view, CutSample here, uint face_class) {
    return inside_view && here.cut_depth > 0.0 && !(face_class == face_class_shell && cut_is_rear_shell(here.texel));
}

// The point `world` seen at model-camera pixel `pixel`, `here` its cut sample, on a face of
// `compact_cell` with `face_info` (common/face_varyings.glsl) and outward unit `face_normal`;
// `edge_opacity`: the cell edge line's there (common/line_style.glsl face_edge_opacity),
// `edge_line`: whether it counts as an edge pixel. Points seen from inside their cell take the
// cut surface's normal, so the cells the cut opens look solid.
SecondaryShade shade_secondary(CutSample here, vec3 world, ivec2 pixel, uint compact_cell, uint face_info,
                               vec3 face_normal, float edge_opacity, bool edge_line) {
    bool inside_view = (face_info & 4u) != 0u;
    SecondaryShade s;
    bool shows_cut = shows_cut_surface(inside_view, here, face_info & 3u);
    s.normal = face_normal;
    // A branch: only cut fill rebuilds the cut's normal. Where the cut is clamped to the rear
    // shell, a shell face seen from inside takes its own plane: the cut's normal there follows
    // the shell's triangles, a shade per triangle.
    if (inside_view) s.normal = shows_cut ? cut_normal_at(here.texel) : -face_normal;
    s.colour = lit(cell_colour(compact_cell), s.normal, world);
    s.flags = (inside_view ? flag_cut_fill : 0u) | (shows_cut ? flag_shows_cut : 0u);
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
        (shell || !hide_lines) && here.fragment_depth - here.cut_depth < border_width * here.fragment_depth / focal_px)
        colour_border(s.colour, s.flags, face_info & 3u, hide_lines, compact_cell, stored_eye_normal(s.normal));
#endif
    return s;
}

// Whether the visible secondary pixel `pixel` (centre `window`), showing the point `world` on a
// face plane of normal `plane_normal`, lies within w of a border (the paper's ray-cast test,
// common/border_test.glsl); never on the model camera's rear shell (freeze view).
bool raycast_border_at(vec2 window, ivec2 pixel, vec3 world, vec3 plane_normal) {
    return !at_view_rear_shell(world, pixel) && raycast_border(window, world, plane_normal);
}

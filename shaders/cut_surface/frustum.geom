#version 450 core
// Stage 1, frustum union: the frustum of one primary cell. Its back face (the box's far side,
// pushed back by the margin, widened by one pixel so pixel-centre coverage never misses) stays;
// the four walls open towards the camera, up to the rim depth (nearest depth of the model:
// nothing in front of it can be cut).
//
// Wall geometry (SPEC section 2 stage 1). As in the paper, the walls are built in the cut
// camera's perspective-divided space (u = x / s, v = y / s, s = depth along the view axis): each
// wall is a PLANE in (u, v, s), so its depth is linear in screen space. In eye space such a wall
// is curved (x = u s), so "its angle" needs a place: at the primary. A wall leans out from the
// view ray through the box edge it starts from by exactly wall_angle (half the user's full
// aperture), measured in eye space at the back face, in the horizontal (x, s) plane for the
// left/right walls and the vertical (y, s) plane for the bottom/top walls. With e = the edge's u
// (or v), phi = atan(e) the angle of its view ray from the axis, and psi = phi +/- wall_angle the
// wall's tangent direction (+ for the left and bottom walls, - for the right and top ones: both
// lean away from the box), the wall is u(s) = e -/+ k (back - s) with
//     k = |tan(psi) - e| / back     (u per depth unit; d(u s)/ds at s = back is tan(psi)),
// flat (k -> infinity, clamped) once psi reaches +-90 degrees: full aperture 180 = flat walls.
// Towards the rim the eye-space wall bends back towards the view ray: on the view axis its mean
// angle between the back face and depth s is atan(tan(angle) s / back); the angle itself holds
// at the primary. Vertices are emitted with w = 1 and z linear in s, so the stored depth is (s - near) / (far - near) and
// interpolates linearly in screen space: the contract of every strategy (cut_surface_strategy.h).
// With CONSTANT_WALL_SLOPE every wall of every box rises wall_u_per_depth in u (or v) per depth
// unit instead: equal pixel slopes, the frustums whose union the frustum-sweep strategy computes
// exactly (tests/gl/frustum_sweep_gl_test.cpp compares the two).
// With OPENING the back face sits `opening` of the way from where the view rays enter the model
// to the box's back: a cut that reaches part of the way to its cell (cut_surface/opening_cut.h),
// nothing at 0, the frustum at 1.
// With BACK_FACE_ONLY defined only the back face is emitted: the cone-field strategies' seeds
// (cut_surface/cut_seeds.h), the primaries' rear hull from their cell boxes.
#include "cut_surface/wall_slope.glsl"

layout(points) in;
layout(triangle_strip, max_vertices = 20) out;

in CellBox {
    vec4 uv_box;
    float far_depth;
    float opening;
    float entry_depth;
} box[];

uniform vec2 projection_scale;   // P[0][0], P[1][1] of the cut camera
uniform float near_plane;
uniform float far_plane;
uniform float rim_depth;         // walls stop here
uniform float back_margin;       // depth units added behind the box
uniform vec2 wall_angle;         // horizontal, vertical: half the full apertures, radians 0..pi/2
uniform float pixel_uv;
#ifdef CONSTANT_WALL_SLOPE
uniform float wall_u_per_depth;
#endif          // one pixel in u, v units (1 / focal length in pixels)

void emit(vec2 uv, float s) {
    gl_Position = vec4(uv * projection_scale, 2.0 * (s - near_plane) / (far_plane - near_plane) - 1.0, 1.0);
    EmitVertex();
}

void main() {
    vec2 lo = box[0].uv_box.xy - pixel_uv;
    vec2 hi = box[0].uv_box.zw + pixel_uv;
    float back = min(box[0].far_depth + back_margin, far_plane);
    float rim = min(rim_depth, back);
    back = mix(clamp(box[0].entry_depth, rim, back), back, box[0].opening);
#ifdef CONSTANT_WALL_SLOPE
    vec2 rim_lo = lo - vec2(wall_u_per_depth * (back - rim));
    vec2 rim_hi = hi + vec2(wall_u_per_depth * (back - rim));
#else
    vec2 rim_lo = lo - wall_slope(lo, -1.0, wall_angle) * (back - rim) / back;
    vec2 rim_hi = hi + wall_slope(hi, 1.0, wall_angle) * (back - rim) / back;
#endif
    // back face
    emit(vec2(lo.x, lo.y), back); emit(vec2(hi.x, lo.y), back); emit(vec2(lo.x, hi.y), back); emit(vec2(hi.x, hi.y), back);
    EndPrimitive();
#ifndef BACK_FACE_ONLY
    // walls: left, right, bottom, top
    emit(vec2(lo.x, lo.y), back); emit(vec2(lo.x, hi.y), back); emit(vec2(rim_lo.x, rim_lo.y), rim); emit(vec2(rim_lo.x, rim_hi.y), rim);
    EndPrimitive();
    emit(vec2(hi.x, lo.y), back); emit(vec2(hi.x, hi.y), back); emit(vec2(rim_hi.x, rim_lo.y), rim); emit(vec2(rim_hi.x, rim_hi.y), rim);
    EndPrimitive();
    emit(vec2(lo.x, lo.y), back); emit(vec2(hi.x, lo.y), back); emit(vec2(rim_lo.x, rim_lo.y), rim); emit(vec2(rim_hi.x, rim_lo.y), rim);
    EndPrimitive();
    emit(vec2(lo.x, hi.y), back); emit(vec2(hi.x, hi.y), back); emit(vec2(rim_lo.x, rim_hi.y), rim); emit(vec2(rim_hi.x, rim_hi.y), rim);
    EndPrimitive();
#endif
}

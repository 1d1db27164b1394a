#version 450 core
// Stage 1, cut volumes: what one triangle of a closed volume removes. With the depth test keeping
// the farthest fragment (GL_GREATER), the union over the volume's triangles is everything between
// the camera and the volume's rear, bevelled as the primaries' frustums are (frustum.geom):
//  - the triangle itself, in clip space with w = s, so its depth is the true depth of the plane
//    (volume.frag writes s; the rear triangles win the max);
//  - for an aperture above 0, walls from it towards the camera, down to the rim depth (nothing in
//    front of the model can be cut). In the perspective-divided space (u, v, s) of frustum.geom the
//    point p's cut is a pyramid whose sides lean out by wall_slope() (the same function, the same
//    --aperture): u in [u_p - l (s_p - s) / s_p, u_p + r (s_p - s) / s_p], likewise v. The union
//    of the pyramids over the triangle is the convex hull of its corners' pyramids; its upper
//    surface is the triangle, one plane through each edge (to the pyramid corner that lies
//    farthest out across the edge, on the side away from the triangle) and, at the corners, the
//    part of the corner's pyramid between two walls (every piece lies inside the hull, so none
//    cuts too much). At aperture 0 the walls follow view rays and cover no pixel:
//    the cut is exactly the volume's silhouette at its rear depth.
// Only rear triangles (facing away from the camera) are drawn: in a closed volume the view ray
// through a front triangle's point leaves the volume through a rear one, farther at the same
// (u, v), whose pyramid holds the front point's (the pyramid widens with depth), so the front
// triangles add nothing to the max and would only double the fill.
// Walls and corner fans only along the silhouette (edges whose neighbour faces the camera),
// leaning out of it: inside the silhouette the rear triangles themselves bound the cut. The walls
// of inner edges, one per edge of every rear triangle, and the inward walls filled the screen many
// times over for the same image wherever the rear surface is less steep than the walls; where it
// is steeper (a vertical face seen from above), a deep corner's pyramid would reach over a
// shallower part: that bevel is left out, the cut follows the volume's rear surface there.
// A triangle with a corner at or in front of the near plane gets no walls (its clipped part is
// drawn; the neighbouring triangles' walls bevel the rest).
#include "cut_surface/wall_slope.glsl"

layout(triangles_adjacency) in;
layout(triangle_strip, max_vertices = 33) out;

in VolumeCorner {
    vec3 eye;
} corner[];

out float eye_depth;  // s, the depth along the cut camera's view axis

uniform vec2 projection_scale;  // P[0][0], P[1][1] of the cut camera
uniform float near_plane;
uniform float far_plane;
uniform float rim_depth;
uniform vec2 wall_angle;        // horizontal, vertical: half the full apertures, radians
uniform float outward_sign;     // +1: triangles wound outward in render space, -1: mirrored

/// A point of the triangle: perspective (w = s), so varyings interpolate as in eye space.
void emit_eye(vec3 eye) {
    float s = -eye.z;
    gl_Position = vec4(eye.xy * projection_scale, s * (2.0 * (s - near_plane) / (far_plane - near_plane) - 1.0), s);
    eye_depth = s;
    EmitVertex();
}

/// A point of a wall, (u, v) at depth s with w = 1: depth linear in screen space, as frustum.geom's.
void emit_uv(vec2 uv, float s) {
    gl_Position = vec4(uv * projection_scale, 2.0 * (s - near_plane) / (far_plane - near_plane) - 1.0, 1.0);
    eye_depth = s;
    EmitVertex();
}

vec2 uv[3];
float depth[3];
float rim[3];
vec2 out_lo[3];  // how far the pyramid reaches left / down at the rim (positive)
vec2 out_hi[3];  // right / up

/// Corner `i`'s pyramid at the rim, on the sides `side` (-1 or +1 per axis).
vec2 rim_corner(int i, vec2 side) {
    return uv[i] + vec2(side.x > 0.0 ? out_hi[i].x : -out_lo[i].x, side.y > 0.0 ? out_hi[i].y : -out_lo[i].y);
}

void emit_edge_wall(int i, int j, vec2 side) {
    emit_uv(uv[i], depth[i]);
    emit_uv(uv[j], depth[j]);
    emit_uv(rim_corner(i, side), rim[i]);
    emit_uv(rim_corner(j, side), rim[j]);
    EndPrimitive();
}

/// The per-axis side (-1 or +1) a direction points to.
vec2 quadrant(vec2 direction) {
    return vec2(direction.x >= 0.0 ? 1.0 : -1.0, direction.y >= 0.0 ? 1.0 : -1.0);
}

/// At silhouette corner `i`, the part of its pyramid between the wall's rim end (on the side
/// `outward` points to) and the side the edge runs on to (`along`, away from the edge): a convex
/// corner turns by less than 180 degrees, so the two edges meeting there, each covering the quarter
/// turn from its outward normal towards its own continuation, close the gap between their walls.
/// Outward and along are perpendicular, so their sides differ in one axis at most: one triangle.
void emit_corner_fan(int i, vec2 outward, vec2 along) {
    vec2 from_side = quadrant(outward), to_side = quadrant(along);
    if (from_side == to_side) return;
    emit_uv(uv[i], depth[i]);
    emit_uv(rim_corner(i, from_side), rim[i]);
    emit_uv(rim_corner(i, to_side), rim[i]);
    EndPrimitive();
}

/// Whether the triangle a b c, wound outward, faces the camera (the eye is at the origin).
bool faces_camera(vec3 a, vec3 b, vec3 c) {
    return dot(outward_sign * cross(b - a, c - a), -a) > 0.0;
}

void main() {
    // Corners 0, 2, 4; vertex 2i + 1 lies across edge (2i, 2i + 2) in the neighbouring triangle.
    vec3 eye[3] = vec3[3](corner[0].eye, corner[2].eye, corner[4].eye);
    if (faces_camera(eye[0], eye[1], eye[2])) return;
    for (int i = 0; i < 3; ++i) emit_eye(eye[i]);
    EndPrimitive();
    if (wall_angle.x <= 0.0 && wall_angle.y <= 0.0) return;
    bool silhouette[3];
    for (int i = 0; i < 3; ++i)  // the neighbour holds the edge the other way round
        silhouette[i] = faces_camera(eye[(i + 1) % 3], eye[i], corner[2 * i + 1].eye);
    if (!silhouette[0] && !silhouette[1] && !silhouette[2]) return;
    for (int i = 0; i < 3; ++i) {
        depth[i] = -eye[i].z;
        if (depth[i] <= near_plane) return;
        uv[i] = eye[i].xy / depth[i];
        rim[i] = min(rim_depth, depth[i]);
        float reach = (depth[i] - rim[i]) / depth[i];
        out_lo[i] = wall_slope(uv[i], -1.0, wall_angle) * reach;
        out_hi[i] = wall_slope(uv[i], 1.0, wall_angle) * reach;
    }
    for (int i = 0; i < 3; ++i) {
        if (!silhouette[i]) continue;
        int j = (i + 1) % 3;
        // The wall leans out of the silhouette: away from the triangle's third corner.
        vec2 across = vec2(uv[i].y - uv[j].y, uv[j].x - uv[i].x);
        if (dot(across, uv[(i + 2) % 3] - uv[i]) > 0.0) across = -across;
        emit_edge_wall(i, j, quadrant(across));
        emit_corner_fan(j, across, uv[j] - uv[i]);
        emit_corner_fan(i, across, uv[i] - uv[j]);
    }
}

// The lean of a cut wall (SPEC section 2 stage 1), shared by the primaries' frustums
// (frustum.geom) and the cut volumes' walls (volume.geom), so both bevel alike for one --aperture.
// In the cut camera's perspective-divided space (u = x / s, v = y / s, s = depth along the view
// axis) a wall from an edge at u = e on the back depth `back` is u(s) = e -/+ k (back - s): it
// leans out from the view ray through the edge by `angle` in eye space, measured at `back`.
/// k * back for the walls from edges `edge` (u and v) on `side` (-1: left/bottom, +1: right/top):
/// |tan(atan(edge) - side * angle) - edge|, 1e4 (far outside any image) once the wall is flat.
vec2 wall_slope(vec2 edge, float side, vec2 angle) {
    const float flat_wall = 1e4;
    vec2 slope;
    for (int axis = 0; axis < 2; ++axis) {
        float psi = atan(edge[axis]) - side * angle[axis];
        slope[axis] = abs(psi) >= 1.5706963 ? flat_wall : min(abs(tan(psi) - edge[axis]), flat_wall);
    }
    return slope;
}

// One face of a cell as every face pass sees it: its 4 corners (face_corners order), outward
// normal (diagonal cross product, unnormalised), and whether the eye sees it from inside its cell.
// Shared by common/face.vert and visibility/cull_cells.comp so the culling pass decides facing
// and collapse exactly as the draw does. Needs common/grid.glsl.
struct FaceFrame {
    vec3 q[4];
    vec3 normal;       // outward, render space, not normalised
    bool back_facing;  // the eye is on the inner side: the face is seen from inside its cell
    bool collapsed;    // zero area (pinch-out): never drawn
    bool any_triangle_front_facing;  // either drawn triangle (0,1,2), (0,2,3) faces the eye (or is edge-on)
};

// The frame of the quad q (a face's 4 corners in face_corners order) of `cell`.
FaceFrame face_frame_of_quad(vec3 q[4], uint cell, vec3 eye) {
    FaceFrame f;
    f.q = q;
    f.normal = cross(f.q[2] - f.q[0], f.q[3] - f.q[1]);
    if (cell_normals_flipped(cell)) f.normal = -f.normal;
    vec3 centre = 0.25 * (f.q[0] + f.q[1] + f.q[2] + f.q[3]);
    f.back_facing = dot(f.normal, eye - centre) < 0.0;
    f.collapsed = dot(f.normal, f.normal) == 0.0;
    // A warped face can have one triangle facing the eye while its centre test says "from
    // inside": a closed cell hides a face only when both of its triangles face away.
    vec3 first = cross(f.q[1] - f.q[0], f.q[2] - f.q[0]), second = cross(f.q[2] - f.q[0], f.q[3] - f.q[0]);
    float sign = cell_normals_flipped(cell) ? -1.0 : 1.0;
    float towards_first = sign * dot(first, eye - f.q[0]), towards_second = sign * dot(second, eye - f.q[0]);
    f.any_triangle_front_facing = towards_first >= 0.0 || towards_second >= 0.0;
    return f;
}

FaceFrame face_frame(uint cell, uint side, vec3 eye) {
    vec3 q[4];
    for (uint k = 0u; k < 4u; ++k) q[k] = corner_position(cell, face_corners[side * 4u + k]);
    return face_frame_of_quad(q, cell, eye);
}

// The same from the cell's 8 corners (corner_position order), rebuilt once by the caller.
FaceFrame face_frame_from_corners(vec3 corners[8], uint cell, uint side, vec3 eye) {
    vec3 q[4];
    for (uint k = 0u; k < 4u; ++k) q[k] = corners[face_corners[side * 4u + k]];
    return face_frame_of_quad(q, cell, eye);
}

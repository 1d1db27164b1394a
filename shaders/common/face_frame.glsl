// One face of a cell as every face pass sees it: its 4 corners (face_corners order), outward
// normal (diagonal cross product, unnormalised), and whether the eye sees it from inside its cell.
// Shared by common/face.vert and visibility/cull_cells.comp so the culling pass decides facing
// and collapse exactly as the draw does. Needs common/grid.glsl.
struct FaceFrame {
    vec3 q[4];
    vec3 normal;       // outward, render space, not normalised
    bool back_facing;  // the eye is on the inner side: the face is seen from inside its cell
    bool collapsed;    // zero area (pinch-out): never drawn
};

FaceFrame face_frame(uint cell, uint side, vec3 eye) {
    FaceFrame f;
    for (uint k = 0u; k < 4u; ++k) f.q[k] = corner_position(cell, face_corners[side * 4u + k]);
    f.normal = cross(f.q[2] - f.q[0], f.q[3] - f.q[1]);
    if (cell_normals_flipped(cell)) f.normal = -f.normal;
    vec3 centre = 0.25 * (f.q[0] + f.q[1] + f.q[2] + f.q[3]);
    f.back_facing = dot(f.normal, eye - centre) < 0.0;
    f.collapsed = dot(f.normal, f.normal) == 0.0;
    return f;
}

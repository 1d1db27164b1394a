// What stage 2's deferred pass (secondary/secondary.frag, DEFERRED) leaves in the scene id
// target's second channel for secondary/deferred_shading.comp, in place of the pixel flags:
// bits 0-2 the face info (common/face_varyings.glsl), bit 3 whether the cell edge line is drawn
// there (its opacity > 0.5, decided before rounding), bits 8-15 the edge line's opacity in 1/255.
uint pack_deferred_face(uint face_info, float edge_opacity) {
    return face_info | (edge_opacity > 0.5 ? 8u : 0u) | (uint(clamp(edge_opacity, 0.0, 1.0) * 255.0 + 0.5) << 8);
}
uint deferred_face_info(uint stored) { return stored & 7u; }
bool deferred_edge_line(uint stored) { return (stored & 8u) != 0u; }
float deferred_edge_opacity(uint stored) { return float((stored >> 8) & 255u) / 255.0; }

#version 450 core
// Cone-field seeds from cell geometry: every face of the primary cells, depth-only with an
// inverted depth test, stored as (s - near) / (far - near) of the cut camera (the strategies'
// depth encoding), so each covered pixel keeps the rear face of the primary cluster.
in FaceVaryings {
#include "common/face_varyings.glsl"
} v_in;

uniform float cut_near;
uniform float cut_far;

void main() { gl_FragDepth = clamp((v_in.cut_eye_depth - cut_near) / (cut_far - cut_near), 0.0, 1.0); }

#version 450 core
// Cone-field seeds from cell geometry: every face of the primary cells, depth-only with an
// inverted depth test, stored as (s - near) / (far - near) of the cut camera (the strategies'
// depth encoding), so each covered pixel keeps the rear face of the primary cluster.
in FaceVaryings {
#include "common/face_varyings.glsl"
} v_in;

// The drawing (cut) camera's planes as plain uniforms, read per fragment (cutaway/face_drawing.h
// set_depth_encoding says why they are not the view block's).
uniform float depth_near, depth_far;

void main() { gl_FragDepth = clamp((v_in.cut_eye_depth - depth_near) / (depth_far - depth_near), 0.0, 1.0); }

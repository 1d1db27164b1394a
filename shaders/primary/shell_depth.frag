#version 450 core
// Stage 3, contours: linear depth of the model's outer shell, uncut; the composite pass finds
// its outline and folds.
in FaceVaryings {
#include "common/face_varyings.glsl"
} v_in;

uniform mat4 model_view;
layout(location = 0) out float out_depth;

void main() { out_depth = -(model_view * vec4(v_in.world_position, 1.0)).z; }

#version 450 core
// Stage 1, frustum union: the depth test (cleared to 0, GL_GREATER) keeps the rear hull.
#include "cut_surface/cut_output.glsl"

in float cut_depth;

void main() { write_cut(cut_depth); }

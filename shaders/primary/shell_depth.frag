#version 450 core
// Stage 3, contours: linear depth of the model's outer shell, uncut; the composite pass finds
// its outline and folds. The depth along the (perspective) camera's axis is the fragment's clip
// w, 1 / gl_FragCoord.w: no varying to set up per triangle or to interpolate.
layout(location = 0) out float out_depth;

void main() { out_depth = 1.0 / gl_FragCoord.w; }

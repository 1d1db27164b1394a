#version 450 core
// Stage 1, frustum union: depth only. The depth test (cleared to 0, GL_GREATER) keeps the rear
// hull; normals are rebuilt once per pixel afterwards (cut_surface/resolve.frag),
// so the many overlapping frustum fragments cost a depth test each and nothing more.
void main() {}

#version 450 core
// The far plane's depth (1) wherever a primary face lies: the rear-shell clamp leaves the cut
// of those pixels as the strategy made it (src/cutaway/rear_shell_depth.h says why).
void main() { gl_FragDepth = 1.0; }

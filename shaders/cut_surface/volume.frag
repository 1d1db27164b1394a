#version 450 core
// Stage 1, cut volumes: the cut's depth (s - near) / (far - near) from the interpolated s, which is
// the true depth on a volume's triangle (perspective interpolation) and linear in screen space on
// its walls (w = 1), as every strategy stores it. Depth clamp is on while the volumes draw, so a
// volume beyond the far plane cuts to the far plane instead of being clipped away.
in float eye_depth;

uniform float near_plane;
uniform float far_plane;

void main() {
    gl_FragDepth = clamp((eye_depth - near_plane) / (far_plane - near_plane), 0.0, 1.0);
}

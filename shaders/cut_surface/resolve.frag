#version 450 core
// Cut surface targets (normal + depth, position) from a strategy's depth image.
uniform sampler2D cut_depth;  // DEPTH32F: (s - near) / (far - near), 0 = nothing cut

float depth_of(ivec2 texel);
#include "cut_surface/cut_output.glsl"

float depth_of(ivec2 texel) {
    if (any(lessThan(texel, ivec2(0))) || any(greaterThanEqual(texel, ivec2(cut_size)))) return 0.0;
    return stored_to_depth(texelFetch(cut_depth, texel, 0).r);
}

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    write_cut(texel, depth_of(texel));
}

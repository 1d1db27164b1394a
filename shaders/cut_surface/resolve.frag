#version 450 core
// Cut surface targets (normal + depth, rear-shell clamp) from a strategy's depth image, kept in front of
// the rear shell unless the frame is see-through (src/cutaway/rear_shell_depth.h).
uniform sampler2D cut_depth;  // DEPTH32F: (s - near) / (far - near), 0 = nothing cut
uniform sampler2D rear_shell_depth;  // the same encoding: the farthest shell face, 0 = none
uniform bool clamp_to_rear_shell;
uniform float rear_margin;    // render units in front of the rear shell

float depth_of(ivec2 texel);
#include "cut_surface/cut_output.glsl"

float depth_of(ivec2 texel) {
    if (any(lessThan(texel, ivec2(0))) || any(greaterThanEqual(texel, ivec2(cut_size)))) return 0.0;
    float s = stored_to_depth(texelFetch(cut_depth, texel, 0).r);
    if (clamp_to_rear_shell && s > 0.0) {
        float rear = stored_to_depth(texelFetch(rear_shell_depth, texel, 0).r);
        if (rear > 0.0) s = min(s, rear - rear_margin);
    }
    return s;
}

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    float s = depth_of(texel);
    write_cut(texel, s);
    // The cut here is the clamp at the rear shell, not the strategy's surface (stage 2 draws no
    // border lines against it: common/cut_lookup.glsl).
    if (s > 0.0 && s < stored_to_depth(texelFetch(cut_depth, texel, 0).r)) out_rear_clamp = 1.0;
}

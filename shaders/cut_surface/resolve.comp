#version 450 core
// Cut surface targets from a strategy's depth image: the depth s per pixel along the cut
// camera's axis (0: no cut), kept rear_margin in front of the rear shell unless the frame is
// see-through (src/cutaway/rear_shell_depth.h), and where it was so clamped. A compute pass over
// image buffers (gl/float_image_buffer.h, src/cutaway/cut_surface/cut_resolve.cpp). The cut's
// normal is not stored: the passes that shade cut fill rebuild it from these depths
// (common/cut_lookup.glsl cut_normal_at), which left this pass no neighbours to read and 12
// bytes per pixel fewer to write.
layout(local_size_x = 64, local_size_y = 4) in;

layout(r32f, binding = 0) uniform readonly imageBuffer cut_depth;         // (s - near) / (far - near), 0 = nothing cut
layout(r32f, binding = 1) uniform readonly imageBuffer rear_shell_depth;  // the same encoding: the farthest shell face, 0 = none
layout(r32f, binding = 2) uniform writeonly image2D surface;              // depth s (0: no cut)
layout(r8, binding = 3) uniform writeonly image2D rear_clamp;             // 1: clamped at the rear shell
uniform bool clamp_to_rear_shell;
uniform float rear_margin;       // render units in front of the rear shell
uniform ivec2 cut_size;          // pixels
uniform float cut_near;          // cut camera near plane
uniform float cut_far;           // cut camera far plane

float stored_to_depth(float stored) { return stored > 0.0 ? cut_near + stored * (cut_far - cut_near) : 0.0; }

// One pixel's targets from the strategy's depth there and the rear shell's (both as depth s).
void resolve_pixel(ivec2 texel, float strategy, float rear) {
    float s = strategy;
    if (clamp_to_rear_shell && s > 0.0 && rear > 0.0) s = min(s, rear - rear_margin);
    if (s <= 0.0) return;  // CutTargets::clear left 0 in both targets (cut_resolve.h)
    imageStore(surface, texel, vec4(s));
    // The cut here is the clamp at the rear shell, not the strategy's surface (stage 2 draws no
    // border lines against it: common/cut_lookup.glsl).
    imageStore(rear_clamp, texel, vec4(s < strategy ? 1.0 : 0.0));
}

#ifdef QUADS
// 4 horizontally adjacent pixels per invocation, the depth images read through their rgba32f
// views (gl::FloatImageBuffer::bind_quad_image; the width a multiple of 4).
layout(rgba32f, binding = 4) uniform readonly imageBuffer cut_depth_quads;
layout(rgba32f, binding = 5) uniform readonly imageBuffer rear_shell_quads;

void main() {
    ivec2 quad = ivec2(gl_GlobalInvocationID.xy);
    int quads = cut_size.x / 4;
    if (quad.x >= quads || quad.y >= cut_size.y) return;
    int index = quad.y * quads + quad.x;
    vec4 strategy = imageLoad(cut_depth_quads, index);
    vec4 rear = clamp_to_rear_shell ? imageLoad(rear_shell_quads, index) : vec4(0.0);
    for (int i = 0; i < 4; ++i)
        resolve_pixel(ivec2(4 * quad.x + i, quad.y), stored_to_depth(strategy[i]), stored_to_depth(rear[i]));
}
#else
void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, cut_size))) return;
    int index = texel.y * cut_size.x + texel.x;
    float rear = clamp_to_rear_shell ? imageLoad(rear_shell_depth, index).r : 0.0;
    resolve_pixel(texel, stored_to_depth(imageLoad(cut_depth, index).r), stored_to_depth(rear));
}
#endif

#version 450 core
// Mean filter of the cut surface's depth image, one axis per pass (AXIS 0: x, 1: y): two passes
// of KERNEL taps give exactly the KERNEL x KERNEL mean with 2k instead of k^2 fetches. SAMPLED
// fetches every other texel along the axis (the sampled kernel: a quarter of the texels of the
// full window). DISTANCE_SCALED shrinks the radius with the pixel's distance to the cut camera
// (src/cutaway/post/mean_filter.h): r = clamp(round(R * reference_depth / s), 1, R), s the
// unfiltered cut's depth at the pixel (R where nothing is cut). The second pass writes the
// filtered depth (same encoding); normals (and the rear-shell clamp) are then rebuilt from it
// (cut_surface/resolve.frag).
uniform sampler2D cut_depth;  // pass 0: the cut's depth; pass 1: the first pass's output
uniform vec2 cut_size;

#ifdef SAMPLED
const int stride = 2;
#else
const int stride = 1;
#endif
const int radius = KERNEL / 2;
const ivec2 axis = AXIS == 0 ? ivec2(1, 0) : ivec2(0, 1);

#if AXIS == 0
layout(location = 0) out float out_depth;
#endif

#ifdef DISTANCE_SCALED
uniform sampler2D unfiltered_depth;  // the cut's depth (both passes): it sets each pixel's radius
uniform float reference_depth;       // render units along the cut camera's axis: the radius is R up to here
uniform vec2 cut_range;              // cut camera near, far planes
int radius_at(ivec2 texel) {
    float stored = texelFetch(unfiltered_depth, texel, 0).r;
    float s = cut_range.x + stored * (cut_range.y - cut_range.x);
    return stored > 0.0 ? clamp(int(round(float(radius) * reference_depth / s)), 1, radius) : radius;
}
#else
int radius_at(ivec2 texel) { return radius; }
#endif

void main() {
    ivec2 centre = ivec2(gl_FragCoord.xy);
    ivec2 last = ivec2(cut_size) - 1;
    int r = radius_at(centre);
    float sum = 0.0;
    float count = 0.0;
    for (int d = -radius; d <= radius; d += stride) {
        if (abs(d) > r) continue;
        sum += texelFetch(cut_depth, clamp(centre + d * axis, ivec2(0), last), 0).r;
        count += 1.0;
    }
#if AXIS == 0
    out_depth = sum / count;
#else
    gl_FragDepth = sum / count;
#endif
}

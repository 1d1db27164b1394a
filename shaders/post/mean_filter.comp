#version 450 core
// Mean filter of the cut surface's depth image, one axis per pass (AXIS 0: x, 1: y): two passes
// of KERNEL taps give exactly the KERNEL x KERNEL mean with 2k instead of k^2 loads; edges
// clamped. SAMPLED loads every other texel along the axis (the sampled kernel: a quarter of the
// texels of the full window). DISTANCE_SCALED shrinks the radius with the pixel's distance to
// the cut camera (src/cutaway/post/mean_filter.h): r = clamp(round(R * reference_depth / s), 1, R),
// s the unfiltered cut's depth at the pixel (R where nothing is cut). Images: float image buffers
// (gl/float_image_buffer.h) holding stored depth (s - near) / (far - near), 0 = nothing cut.
// QUADS: the full kernel over 4 pixels per invocation (below).
layout(local_size_x = 64, local_size_y = 4) in;

layout(r32f, binding = 0) uniform readonly imageBuffer source;  // pass 0: the cut's depth; pass 1: pass 0's output
layout(r32f, binding = 1) uniform writeonly imageBuffer filtered;
uniform ivec2 size;  // pixels

#ifdef SAMPLED
const int stride = 2;
#else
const int stride = 1;
#endif
const int radius = KERNEL / 2;
const ivec2 axis = AXIS == 0 ? ivec2(1, 0) : ivec2(0, 1);

int index_of(ivec2 texel) { return texel.y * size.x + texel.x; }

#ifdef DISTANCE_SCALED
layout(r32f, binding = 2) uniform readonly imageBuffer unfiltered;  // the cut's depth (both passes): each pixel's radius
uniform float reference_depth;  // render units along the cut camera's axis: the radius is R up to here
uniform vec2 cut_range;         // cut camera near, far planes
int radius_at(ivec2 texel) {
    float stored = imageLoad(unfiltered, index_of(texel)).r;
    float s = cut_range.x + stored * (cut_range.y - cut_range.x);
    return stored > 0.0 ? clamp(int(round(float(radius) * reference_depth / s)), 1, radius) : radius;
}
#else
int radius_at(ivec2 texel) { return radius; }
#endif

#ifdef QUADS
// The full kernel, 4 horizontally adjacent pixels per invocation, through the images' rgba32f
// views (gl::FloatImageBuffer::bind_quad_image; the width a multiple of 4): each pixel's sum
// takes the same taps in the same order as one invocation per pixel does, so the result is the
// same to the bit, with a quarter of the image calls.
layout(rgba32f, binding = 0) uniform readonly imageBuffer source_quads;
layout(rgba32f, binding = 1) uniform writeonly imageBuffer filtered_quads;

void main() {
    ivec2 quad = ivec2(gl_GlobalInvocationID.xy);  // x: which 4 pixels of the row
    int quads = size.x / 4;
    if (quad.x >= quads || quad.y >= size.y) return;
    vec4 sum = vec4(0.0);
#if AXIS == 0
    const int reach = (radius + 3) / 4;  // quads on each side that the window reaches
    float row[4 * (2 * reach + 1)];      // the row's pixels from 4 * (quad.x - reach) on
    for (int q = -reach; q <= reach; ++q) {
        int at = quad.x + q;
        vec4 texel = imageLoad(source_quads, quad.y * quads + clamp(at, 0, quads - 1));
        texel = at < 0 ? vec4(texel.x) : at >= quads ? vec4(texel.w) : texel;  // edges clamped, as per pixel
        for (int i = 0; i < 4; ++i) row[4 * (q + reach) + i] = texel[i];
    }
    for (int i = 0; i < 4; ++i)
        for (int d = -radius; d <= radius; ++d) sum[i] += row[4 * reach + i + d];
#else
    for (int d = -radius; d <= radius; ++d) sum += imageLoad(source_quads, clamp(quad.y + d, 0, size.y - 1) * quads + quad.x);
#endif
    imageStore(filtered_quads, quad.y * quads + quad.x, sum / float(KERNEL));
}
#else
void main() {
    ivec2 centre = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(centre, size))) return;
    int r = radius_at(centre);
    float sum = 0.0;
    float count = 0.0;
    for (int d = -radius; d <= radius; d += stride) {
        float value = imageLoad(source, index_of(clamp(centre + d * axis, ivec2(0), size - 1))).r;
        bool inside = abs(d) <= r;  // selects, not branches: SIMD lanes on a CPU rasteriser stay together
        sum += inside ? value : 0.0;
        count += inside ? 1.0 : 0.0;
    }
    imageStore(filtered, index_of(centre), vec4(sum / count));
}
#endif

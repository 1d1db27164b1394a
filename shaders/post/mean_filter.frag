#version 450 core
// Mean filter of the cut surface's depth image over a KERNEL x KERNEL window, removing the
// staircase between frustums. SAMPLED fetches every other texel in each direction (about a
// quarter of the texels) instead of all of them. Writes the filtered depth (same encoding);
// normals and positions are then rebuilt from it (cut_surface/resolve.frag).
uniform sampler2D cut_depth;
uniform vec2 cut_size;

#ifdef SAMPLED
const int stride = 2;
#else
const int stride = 1;
#endif
const int radius = KERNEL / 2;

void main() {
    ivec2 centre = ivec2(gl_FragCoord.xy);
    ivec2 last = ivec2(cut_size) - 1;
    float sum = 0.0;
    float count = 0.0;
    for (int dy = -radius; dy <= radius; dy += stride)
        for (int dx = -radius; dx <= radius; dx += stride) {
            sum += texelFetch(cut_depth, clamp(centre + ivec2(dx, dy), ivec2(0), last), 0).r;
            count += 1.0;
        }
    gl_FragDepth = sum / count;
}

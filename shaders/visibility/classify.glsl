// Where a cell or a brick lies against the model camera's frustum and the cut (SPEC.md section 6),
// shared by visibility/classify_bricks.comp and visibility/cull_cells.comp: culled (outside the
// frustum), in front of the cut (every fragment discarded), behind it (every fragment kept) or
// straddling it.
// visibility/cut_pyramid.comp's (min, max) pairs as RG32F texels: on llvmpipe a storage-buffer load
// at an index that varies across SIMD lanes runs lane by lane, a texel fetch is one gather (the
// culling's cell pass at 1080p on sapphire ran faster so).
uniform samplerBuffer pyramid_texels;

// ViewCamera: the model camera; CutCamera: the cut camera (the model camera unless the view is frozen).
#include "common/cameras.glsl"
uniform bool has_cut;           // false: nothing is cut anywhere (plain frame)
const int max_pyramid_levels = 16;
uniform int pyramid_levels;     // levels of the pyramid (its level 0 is half the cut image)
uniform ivec2 pyramid_sizes[max_pyramid_levels];
uniform int pyramid_offsets[max_pyramid_levels];
uniform sampler2D cut_surface;  // R32F: cut depth along the cut camera's axis, 0 = nothing cut

// Freeze view: stage 2 keeps the model camera's rear shell in front of the cut too
// (common/cut_lookup.glsl), so a cell in front of the cut still gives its exposed faces seen from
// inside (the only ones that can lie on that rear shell).
uniform bool keep_rear_faces;

const int culled = 0, in_front = 1, behind = 2, straddling = 3;

// Min and max cut depth over the texel rectangle lo..hi (inclusive, inside the cut image).
vec2 cut_range(ivec2 lo, ivec2 hi) {
    int extent = max(hi.x - lo.x, hi.y - lo.y) + 1;
    int level = 0;
    while ((4 << level) < extent) ++level;  // the rectangle spans at most 5x5 texels there
    level = min(level, pyramid_levels);
    vec2 range = vec2(3.0e38, -3.0e38);
    if (level == 0) {
        for (int y = lo.y; y <= hi.y; ++y)
            for (int x = lo.x; x <= hi.x; ++x) {
                float depth = texelFetch(cut_surface, ivec2(x, y), 0).r;
                range = vec2(min(range.x, depth), max(range.y, depth));
            }
        return range;
    }
    ivec2 size = pyramid_sizes[level - 1];
    int offset = pyramid_offsets[level - 1];
    ivec2 a = min(lo >> level, size - 1), b = min(hi >> level, size - 1);
    for (int y = a.y; y <= b.y; ++y)
        for (int x = a.x; x <= b.x; ++x) {
            vec2 r = texelFetch(pyramid_texels, offset + y * size.x + x).rg;
            range = vec2(min(range.x, r.x), max(range.y, r.y));
        }
    return range;
}

// Where a convex hull of 8 points (a cell, or a brick's box) lies. Slack of 1e-5 relative keeps
// float rounding between this pass and the draw on the conservative side.
int classify_first(vec3 p[8], int n) {
    uint outside_all = 63u;
    float near_depth = 3.0e38, far_depth = -3.0e38;
    vec2 lo = vec2(3.0e38), hi = vec2(-3.0e38);
    bool behind_cut_eye = false;
    for (int k = 0; k < n; ++k) {
        vec4 c = view_projection * vec4(p[k], 1.0);
        float s = 1e-5 * (abs(c.x) + abs(c.y) + abs(c.z) + abs(c.w));
        uint outside = (c.x < -c.w - s ? 1u : 0u) | (c.x > c.w + s ? 2u : 0u) | (c.y < -c.w - s ? 4u : 0u) |
                       (c.y > c.w + s ? 8u : 0u) | (c.z < -c.w - s ? 16u : 0u) | (c.z > c.w + s ? 32u : 0u);
        outside_all &= outside;
#ifdef CUT_CAMERA_IS_VIEW
        // The cut camera is the model camera (a perspective one): its clip position is c and the
        // depth along its axis c.w, one matrix product per corner instead of three.
        float depth = c.w;
        vec4 cc = c;
#else
        float depth = -(cut_view * vec4(p[k], 1.0)).z;
        vec4 cc = cut_view_projection * vec4(p[k], 1.0);
#endif
        near_depth = min(near_depth, depth);
        far_depth = max(far_depth, depth);
        if (cc.w <= 1e-6) {
            behind_cut_eye = true;
        } else {
            // Clamped so a corner just in front of the eye (tiny w) cannot overflow the int
            // conversion below; the rectangle is clamped to the image anyway.
            vec2 t = clamp((cc.xy / cc.w * 0.5 + 0.5) * cut_size, vec2(-1.0e6), vec2(1.0e6));
            lo = min(lo, t);
            hi = max(hi, t);
        }
    }
    if (outside_all != 0u) return culled;
    if (!has_cut) return behind;
    if (behind_cut_eye) return straddling;
    ivec2 size = ivec2(cut_size);
    ivec2 tlo = ivec2(floor(lo)) - 1, thi = ivec2(floor(hi)) + 1;  // a texel of margin
    if (any(lessThan(thi, ivec2(0))) || any(greaterThanEqual(tlo, size))) return behind;  // no cut outside the image
    bool partly_outside = any(lessThan(tlo, ivec2(0))) || any(greaterThanEqual(thi, size));
    vec2 cut = cut_range(clamp(tlo, ivec2(0), size - 1), clamp(thi, ivec2(0), size - 1));
    if (partly_outside) cut.x = 0.0;
    float eps = 1e-5 * max(abs(near_depth), abs(far_depth));
    if (far_depth + eps < cut.x) return in_front;   // fragment depth < cut everywhere: all discarded
    if (near_depth - eps >= cut.y) return behind;   // fragment depth >= cut everywhere: all kept
    return straddling;
}

int classify(vec3 p[8]) { return classify_first(p, 8); }

int classify_box(vec3 lo, vec3 hi) {
    vec3 p[8];
    for (int k = 0; k < 8; ++k) p[k] = vec3((k & 1) != 0 ? hi.x : lo.x, (k & 2) != 0 ? hi.y : lo.y, (k & 4) != 0 ? hi.z : lo.z);
    return classify(p);
}

// Whether a brick or cell of this class gives no face at all.
bool gives_nothing(int where) { return where == culled || (where == in_front && !keep_rear_faces); }

// The seed of a cone-field transform at a texel: the stored depth t of the seed image
// (0 = no seed), or with WIDEN_SEEDS the max over the texel's 3x3 neighbourhood (the geometry
// seeds' one-pixel widening, cut_seeds.cpp's widened_by_one_pixel).
uniform sampler2D seeds;  // DEPTH32F, rows bottom to top

float seed_at(ivec2 texel) {
#ifdef WIDEN_SEEDS
    ivec2 size = textureSize(seeds, 0);
    float deepest = 0.0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            ivec2 n = texel + ivec2(dx, dy);
            if (all(greaterThanEqual(n, ivec2(0))) && all(lessThan(n, size))) deepest = max(deepest, texelFetch(seeds, n, 0).r);
        }
    return deepest;
#else
    return texelFetch(seeds, texel, 0).r;
#endif
}

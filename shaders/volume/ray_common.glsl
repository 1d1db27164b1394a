// Helpers shared with the CPU reference caster (src/volume/ray_march.cpp): the same hash, table
// read and block exit distance, so both take the same samples and classify them alike.

// PCG hash (Jarzynski & Olano 2020).
uint pcg_hash(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

// Fraction of a step in [0, 1) for a pixel: top 24 bits, exact in a float.
float jitter_fraction(uvec2 pixel) {
    return float(pcg_hash(pixel.x + pcg_hash(pixel.y)) >> 8u) * (1.0 / 16777216.0);
}

// The 256-entry table at a continuous level, linear between entries (texelFetch, no filtering).
vec4 lookup_table(sampler1D table, float level) {
    float x = clamp(level, 0.0, 255.0);
    int i = min(int(x), 254);
    float f = x - float(i);
    vec4 a = texelFetch(table, i, 0);
    vec4 b = texelFetch(table, i + 1, 0);
    return a + f * (b - a);
}

// Distance along dir from p (inside `block`) to the block's far boundary.
float block_exit_distance(vec3 p, vec3 dir, ivec3 block, float block_size) {
    float exit_distance = 3.4e38;
    for (int axis = 0; axis < 3; ++axis) {
        if (dir[axis] == 0.0) continue;
        float bound = (float(block[axis]) + (dir[axis] > 0.0 ? 1.0 : 0.0)) * block_size;
        exit_distance = min(exit_distance, (bound - p[axis]) / dir[axis]);
    }
    return exit_distance;
}

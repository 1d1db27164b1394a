#version 450 core
// Chamfer propagation on the GPU (gpu_chamfer.cpp) as 1-D max-plus dilations along lattice lines:
// one invocation per line of direction `direction` through the image (lines are disjoint, so
// each updates its pixels in place), a forward then a backward sweep: h(p) = max(h(p),
// h(p -+ direction) - weight). Heights in stored depth units t.
// Variant INIT: the heights image from the seed image (cone_seed.glsl); no seed: far below 0.
layout(local_size_x = 64) in;

layout(r32f, binding = 0) uniform coherent image2D heights;

const float no_height = -3.0e38;

#ifdef INIT
#include "cut_surface/cone_seed.glsl"

void main() {
    ivec2 size = imageSize(heights);
    int index = int(gl_GlobalInvocationID.x);
    if (index >= size.x * size.y) return;
    ivec2 p = ivec2(index % size.x, index / size.x);
    float seed = seed_at(p);
    imageStore(heights, p, vec4(seed > 0.0 ? seed : no_height));
}
#else
uniform ivec2 direction;  // x > 0, or x == 0 and y > 0
uniform float weight;     // slope (stored units per pixel) x the step's chamfer length

/// The first pixel of line `line`: lines start where p - direction leaves the image, first
/// those in the columns x < direction.x, then those in the rows the direction enters through.
ivec2 line_start(int line, ivec2 size) {
    int columns = min(direction.x, size.x);
    if (line < columns * size.y) return ivec2(line / size.y, line % size.y);
    line -= columns * size.y;
    int row = line / (size.x - columns);
    int x = columns + line % (size.x - columns);
    return ivec2(x, direction.y > 0 ? row : size.y - 1 - row);
}

uniform int line_count;

bool inside(ivec2 p, ivec2 size) { return all(greaterThanEqual(p, ivec2(0))) && all(lessThan(p, size)); }

void main() {
    int line = int(gl_GlobalInvocationID.x);
    if (line >= line_count) return;
    ivec2 size = imageSize(heights);
    ivec2 p = line_start(line, size);
    float run = no_height;
    int length = 0;
    for (; inside(p, size); p += direction, ++length) {
        run = max(imageLoad(heights, p).r, run - weight);
        imageStore(heights, p, vec4(run));
    }
    run = no_height;
    for (p -= direction; length > 0; p -= direction, --length) {
        run = max(imageLoad(heights, p).r, run - weight);
        imageStore(heights, p, vec4(run));
    }
}
#endif

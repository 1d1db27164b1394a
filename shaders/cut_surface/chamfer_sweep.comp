#version 450 core
// Chamfer propagation on the GPU (gpu_chamfer.cpp) as 1-D max-plus dilations along lattice lines:
// one invocation per line of direction `direction` through the image (lines are disjoint, so
// each updates its pixels in place), a forward then a backward sweep: h(p) = max(h(p),
// h(p -+ direction) - weight). Heights in stored depth units t.
// Variant INIT: the sweep along the rows (direction (1, 0)) reading its forward pass from the
// seed image (cone_seed.glsl; no seed: far below 0) instead of the heights image, so the heights
// need no pass of their own (sapphire at 1920x1080: the separate pass was a noticeable cost).
layout(local_size_x = 64) in;

layout(r32f, binding = 0) uniform coherent image2D heights;

const float no_height = -3.0e38;

uniform float weight;     // slope (stored units per pixel) x the step's chamfer length

// The forward pass's start value at p and its stored height; the store is skipped where a pass
// leaves the height as it was (a sweep changes only the pixels a seed's cone rises above).
#ifdef INIT
#include "cut_surface/cone_seed.glsl"

float forward_height(ivec2 p) {
    float seed = seed_at(p);
    return seed > 0.0 ? seed : no_height;
}
#else
float forward_height(ivec2 p) { return imageLoad(heights, p).r; }
#endif

// One step of a pass: h(p) = max(h(p), run - weight), `here` the height at p before the step.
float step_to(ivec2 p, float here, float run, bool stored) {
    float carried = run - weight;
    if (carried > here || !stored) imageStore(heights, p, vec4(max(carried, here)));
    return max(carried, here);
}

#ifdef INIT
const ivec2 direction = ivec2(1, 0);
#else
uniform ivec2 direction;  // x > 0, or x == 0 and y > 0
#endif

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
#ifdef INIT
    const bool stored = false;  // the heights image holds nothing yet: every pixel is stored
#else
    const bool stored = true;
#endif
    for (; inside(p, size); p += direction, ++length) run = step_to(p, forward_height(p), run, stored);
    run = no_height;
    for (p -= direction; length > 0; p -= direction, --length) run = step_to(p, imageLoad(heights, p).r, run, true);
}

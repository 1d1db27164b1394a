#version 450 core
// Exclusive prefix sums of the per-word counts, in place, by one workgroup: each invocation sums
// a contiguous run of words, the run totals are scanned in shared memory, then each invocation
// writes its run's offsets. The grand totals go to `totals` (read back to size the lists).
#include "common/shared_constants.h"
layout(local_size_x = 256) in;

layout(std430, binding = ssbo_word_counts) buffer WordCounts { uvec2 word_counts[]; };
layout(std430, binding = ssbo_selection_totals) writeonly buffer Totals { uvec2 totals; };

uniform uint word_total;

shared uvec2 run_offsets[256];

void main() {
    uint lane = gl_LocalInvocationIndex;
    uint run = (word_total + 255u) / 256u;
    uint first = min(lane * run, word_total), last = min(first + run, word_total);
    uvec2 sum = uvec2(0u);
    for (uint w = first; w < last; ++w) sum += word_counts[w];
    run_offsets[lane] = sum;
    barrier();
    if (lane == 0u) {
        uvec2 offset = uvec2(0u);
        for (uint i = 0u; i < 256u; ++i) {
            uvec2 count = run_offsets[i];
            run_offsets[i] = offset;
            offset += count;
        }
        totals = offset;
    }
    barrier();
    uvec2 offset = run_offsets[lane];
    for (uint w = first; w < last; ++w) {
        uvec2 count = word_counts[w];
        word_counts[w] = offset;
        offset += count;
    }
}

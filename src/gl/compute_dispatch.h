#pragma once
// Compute dispatches: workgroup counts of any size, and waiting for draws before image loads.
#include <algorithm>
#include <cstddef>
#include <utility>

#include "gl/gl_objects.h"

namespace cutaway::gl {

/// `groups` workgroups as (X, Y) counts, spread over Y beyond the 65535 groups GL guarantees
/// along X; the shader computes its group index as gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x
/// and skips indices past the end.
inline std::pair<GLuint, GLuint> dispatch_grid(std::size_t groups) {
    const std::size_t groups_x = std::min<std::size_t>(std::max<std::size_t>(groups, 1), 65535);
    return {GLuint(groups_x), GLuint((std::max<std::size_t>(groups, 1) + groups_x - 1) / groups_x)};
}

/// Call before a compute pass that reads render targets as images: llvmpipe rasterises
/// asynchronously, and only a barrier (or binding the texture for sampling) makes the pass wait for
/// the draws into them. Without it the ray-cast border pass read stale face planes (the
/// GoldenImages and CutawayBorders tests).
inline void wait_for_draws_before_image_loads() { glMemoryBarrier(GL_ALL_BARRIER_BITS); }

/// Groups of `group` invocations covering `count`.
inline unsigned group_count(int count, int group) { return unsigned((count + group - 1) / group); }

/// Dispatches the bound compute `program` with one invocation per cell of a `width` x `height`
/// grid, in workgroups of the size its shader declares, so each pass keeps the size that measured
/// best for it on llvmpipe (1920x1080, sapphire, alternating runs): SSAO faster in 64 x 16
/// groups than in 64 x 4 (a workgroup has a fixed cost), the composite slower so and fastest in
/// rows of 128.
inline void dispatch_over(const Program& program, int width, int height) {
    GLint size[3] = {1, 1, 1};
    glGetProgramiv(program.id(), GL_COMPUTE_WORK_GROUP_SIZE, size);
    glDispatchCompute(group_count(width, size[0]), group_count(height, size[1]), 1);
}

}  // namespace cutaway::gl

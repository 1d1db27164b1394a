#include "cutaway/selection/primary_centroid.h"

#include <algorithm>
#include <vector>

#include "common/shared_constants.h"
#include "gl/uniforms.h"

namespace cutaway::pipeline {
namespace {
constexpr GLuint partial_sums_binding = shared::ssbo_centroid_partial_sums;  // primary_centroid.comp
constexpr std::size_t group_size = 256;
}  // namespace

PrimaryCentroid::PrimaryCentroid(const gl::ShaderLibrary& shaders)
    : program_(shaders.build({{GL_COMPUTE_SHADER, "selection/primary_centroid.comp"}})) {}

CentreSum PrimaryCentroid::centre_sum(const GridBuffers& grid) {
    const std::size_t count = grid.primary_cells().count;
    if (count == 0) return {};
    const std::size_t groups = (count + group_size - 1) / group_size;
    const std::size_t bytes = groups * sizeof(glm::vec4);
    if (partial_sums_.size_bytes() < bytes) partial_sums_ = gl::Buffer(bytes, nullptr);
    grid.set_geometry_uniforms(program_);
    gl::set_uniform(program_, "primary_count", unsigned(count));
    grid.bind_geometry();
    grid.primary_cells().buffer.bind_base(GL_SHADER_STORAGE_BUFFER, primary_cells_binding);
    partial_sums_.bind_base(GL_SHADER_STORAGE_BUFFER, partial_sums_binding);
    program_.use();
    const std::size_t groups_x = std::min<std::size_t>(groups, 65535);
    glDispatchCompute(GLuint(groups_x), GLuint((groups + groups_x - 1) / groups_x), 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<glm::vec4> partial(groups);
    glGetNamedBufferSubData(partial_sums_.id(), 0, GLsizeiptr(bytes), partial.data());
    CentreSum sum{glm::dvec3(0), count};
    for (const glm::vec4& p : partial) sum.sum += glm::dvec3(p);
    return sum;
}

}  // namespace cutaway::pipeline

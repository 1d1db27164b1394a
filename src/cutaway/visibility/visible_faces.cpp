#include "cutaway/visibility/visible_faces.h"

#include <algorithm>
#include <array>
#include <span>

#include "gl/uniforms.h"

namespace cutaway::pipeline {
namespace {

enum CullingBinding : unsigned { brick_cells_binding = 6, brick_begin_binding = 7, brick_boxes_binding = 8,
                                 culling_binding = 11, visible_faces_binding = 12, draw_commands_binding = 14 };

/// The counters of visibility/cull_cells.comp.
constexpr std::array<std::uint32_t, 5> cleared_counters{0, 0, 0, 0, 0};
/// DrawElementsIndirectCommand: count, instance count, first index, base vertex, base instance.
constexpr std::size_t draw_command_bytes = 5 * sizeof(std::uint32_t);

}  // namespace

VisibleFaces::VisibleFaces(const gl::ShaderLibrary& shaders, const CellBricks& bricks, std::size_t face_capacity)
    : cull_(shaders.build({{GL_COMPUTE_SHADER, "visibility/cull_cells.comp"}})),
      finish_(shaders.build({{GL_COMPUTE_SHADER, "visibility/finish_culling.comp"}})),
      pyramid_(shaders),
      brick_cells_(gl::Buffer::from(std::span<const std::uint32_t>(bricks.cells))),
      brick_begin_(gl::Buffer::from(std::span<const std::uint32_t>(bricks.begin))),
      brick_boxes_(gl::Buffer::from(std::span<const float>(bricks.boxes))),
      brick_count_(bricks.brick_count()),
      face_capacity_(std::max<std::size_t>(face_capacity, 1)),
      counters_(sizeof(cleared_counters), cleared_counters.data(), GL_DYNAMIC_STORAGE_BIT),
      faces_(face_capacity_ * sizeof(std::uint32_t), nullptr),
      chunks_(QuadDraw::chunks_for(face_capacity_)),
      commands_(chunks_ * draw_command_bytes, nullptr) {}

void VisibleFaces::select(const GridBuffers& grid, const Camera& camera, const CutTargets* cut, const Camera& cut_camera,
                          bool keep_rear_faces) {
    if (cut) pyramid_.build(cut->surface);
    glNamedBufferSubData(counters_.id(), 0, sizeof(cleared_counters), cleared_counters.data());
    const gl::Program& p = cull_;
    gl::set_uniform(p, "grid_size", grid.grid_size());
    gl::set_uniform(p, "up_sign", float(grid.frame().up_sign));
    gl::set_uniform(p, "z_scale", float(grid.frame().z_scale));
    gl::set_uniform(p, "view_projection", camera.view_projection());
    gl::set_uniform(p, "eye_position", camera.eye);
    gl::set_uniform(p, "cut_view", cut_camera.view);
    gl::set_uniform(p, "cut_view_projection", cut_camera.view_projection());
    gl::set_uniform(p, "cut_size", glm::vec2(float(cut_camera.width), float(cut_camera.height)));
    gl::set_uniform(p, "has_cut", cut != nullptr);
    gl::set_uniform(p, "keep_rear_faces", keep_rear_faces);
    gl::set_uniform(p, "brick_count", unsigned(brick_count_));
    gl::set_uniform(p, "face_capacity", unsigned(face_capacity_));
    gl::set_uniform(p, "cut_surface", 0);
    if (cut) cut->surface.bind(0);
    pyramid_.bind_for(p);
    grid.bind_geometry();
    grid.bind_culling_inputs();
    brick_cells_.bind_base(GL_SHADER_STORAGE_BUFFER, brick_cells_binding);
    brick_begin_.bind_base(GL_SHADER_STORAGE_BUFFER, brick_begin_binding);
    brick_boxes_.bind_base(GL_SHADER_STORAGE_BUFFER, brick_boxes_binding);
    counters_.bind_base(GL_SHADER_STORAGE_BUFFER, culling_binding);
    faces_.bind_base(GL_SHADER_STORAGE_BUFFER, visible_faces_binding);
    p.use();
    // One workgroup per brick, spread over Y beyond the 65535 groups GL guarantees along X.
    const std::size_t groups_x = std::min<std::size_t>(std::max<std::size_t>(brick_count_, 1), 65535);
    const std::size_t groups_y = (std::max<std::size_t>(brick_count_, 1) + groups_x - 1) / groups_x;
    glDispatchCompute(GLuint(groups_x), GLuint(groups_y), 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    gl::set_uniform(finish_, "face_capacity", unsigned(face_capacity_));
    gl::set_uniform(finish_, "chunk_count", unsigned(chunks_));
    gl::set_uniform(finish_, "quads_per_chunk", QuadDraw::quads_per_chunk);
    commands_.bind_base(GL_SHADER_STORAGE_BUFFER, draw_commands_binding);
    finish_.use();
    glDispatchCompute(GLuint((chunks_ + 63) / 64), 1, 1);
    glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
}

void VisibleFaces::draw(const GridBuffers& grid) const {
    faces_.bind_base(GL_SHADER_STORAGE_BUFFER, faces_binding);
    grid.quads().draw_indirect(commands_, chunks_);
}

CullingCounts VisibleFaces::read_counts() const {
    std::array<std::uint32_t, cleared_counters.size()> c{};
    glGetNamedBufferSubData(counters_.id(), 0, sizeof(c), c.data());
    return {std::min<std::uint64_t>(c[4], face_capacity_), c[4], brick_count_, c[0], c[1], c[2], c[3]};
}

std::size_t VisibleFaces::memory_bytes() const {
    return brick_cells_.size_bytes() + brick_begin_.size_bytes() + brick_boxes_.size_bytes() + faces_.size_bytes() +
           counters_.size_bytes() + commands_.size_bytes() + pyramid_.memory_bytes();
}

}  // namespace cutaway::pipeline

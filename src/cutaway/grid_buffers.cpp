#include "cutaway/grid_buffers.h"

#include <span>

namespace cutaway::pipeline {

FaceBuffer FaceBuffer::from(const std::vector<std::uint32_t>& records) {
    return {gl::Buffer::from(std::span<const std::uint32_t>(records)), records.size()};
}

GridBuffers::GridBuffers(const GridLayout& layout, const grid::GridDims& dims, const ModelFrame& frame)
    : grid_size_(unsigned(dims.nx), unsigned(dims.ny)),
      frame_(frame),
      pillars_(gl::Buffer::from(std::span<const float>(layout.pillars))),
      corner_depths_(gl::Buffer::from(std::span<const float>(layout.corner_depths))),
      cells_(gl::Buffer::from(std::span<const std::uint32_t>(layout.cells))),
      values_(layout.cells.size() * sizeof(float), nullptr, GL_DYNAMIC_STORAGE_BIT),
      shell_(FaceBuffer::from(pipeline::shell_faces(layout))),
      all_(FaceBuffer::from(pipeline::all_faces(layout))) {}

void GridBuffers::set_values(const std::vector<float>& compact_values) {
    glNamedBufferSubData(values_.id(), 0, GLsizeiptr(compact_values.size() * sizeof(float)), compact_values.data());
}

void GridBuffers::set_selection(const FaceLists& lists) {
    secondary_ = FaceBuffer::from(lists.secondary);
    primary_ = FaceBuffer::from(lists.primary);
    primary_cells_ = FaceBuffer::from(lists.primary_cells);
}

void GridBuffers::bind_geometry() const {
    pillars_.bind_base(GL_SHADER_STORAGE_BUFFER, pillars_binding);
    corner_depths_.bind_base(GL_SHADER_STORAGE_BUFFER, corner_depths_binding);
    cells_.bind_base(GL_SHADER_STORAGE_BUFFER, cells_binding);
    values_.bind_base(GL_SHADER_STORAGE_BUFFER, values_binding);
}

void GridBuffers::draw_faces(const FaceBuffer& faces) {
    if (faces.count == 0) return;
    faces.buffer.bind_base(GL_SHADER_STORAGE_BUFFER, faces_binding);
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(6 * faces.count));
}

}  // namespace cutaway::pipeline

#include "cutaway/grid_buffers.h"

#include <algorithm>
#include <span>

namespace cutaway::pipeline {

FaceBuffer FaceBuffer::from(const std::vector<std::uint32_t>& records) {
    return {gl::Buffer::from(std::span<const std::uint32_t>(records)), records.size()};
}

namespace {
/// 2 bits per side (FaceClass), sides in FaceSide order, one word per active cell.
std::vector<std::uint32_t> packed_face_classes(const GridLayout& layout) {
    std::vector<std::uint32_t> packed(layout.cells.size(), 0);
    for (std::size_t c = 0; c < packed.size(); ++c)
        for (std::size_t s = 0; s < 6; ++s) packed[c] |= std::uint32_t(layout.face_classes[6 * c + s]) << (2 * s);
    return packed;
}
/// Per active cell as the shaders read it (common/grid.glsl): the pillar index of its corner 0
/// (bits 0-30) and the flip bit of GridLayout::cells (bit 31).
std::vector<std::uint32_t> gpu_cell_records(const GridLayout& layout, const grid::GridDims& dims) {
    std::vector<std::uint32_t> records(layout.cells.size());
    for (std::size_t c = 0; c < records.size(); ++c) {
        const std::size_t eclipse = layout.cells[c] & 0x7fffffffu;
        const std::size_t i = eclipse % std::size_t(dims.nx), j = eclipse / std::size_t(dims.nx) % std::size_t(dims.ny);
        records[c] = std::uint32_t(j * std::size_t(dims.nx + 1) + i) | (layout.cells[c] & 0x80000000u);
    }
    return records;
}
}  // namespace

GridBuffers::GridBuffers(const GridLayout& layout, const grid::GridDims& dims, const ModelFrame& frame)
    : layout_(layout),
      grid_size_(unsigned(dims.nx), unsigned(dims.ny)),
      frame_(frame),
      pillars_(gl::Buffer::from(std::span<const float>(layout.pillars))),
      corner_depths_(gl::Buffer::from(std::span<const float>(layout.corner_depths))),
      cells_(gl::Buffer::from(std::span<const std::uint32_t>(gpu_cell_records(layout, dims)))),
      values_(layout.cells.size() * sizeof(float), nullptr, GL_DYNAMIC_STORAGE_BIT),
      cell_face_classes_(gl::Buffer::from(std::span<const std::uint32_t>(packed_face_classes(layout)))),
      primary_bits_((layout.cells.size() + 31) / 32 * sizeof(std::uint32_t) + sizeof(std::uint32_t), nullptr,
                    GL_DYNAMIC_STORAGE_BIT),
      shell_(FaceBuffer::from(pipeline::shell_faces(layout))),
      outer_(FaceBuffer::from(pipeline::outer_faces(layout))),
      pillar_texels_(pillars_, GL_RGBA32F),
      corner_depth_texels_(corner_depths_, GL_R32F),
      cell_texels_(cells_, GL_R32UI),
      value_texels_(values_, GL_R32F) {}

const FaceBuffer& GridBuffers::all_faces() const {
    if (!all_.buffer) all_ = FaceBuffer::from(pipeline::all_faces(layout_));
    return all_;
}

std::size_t GridBuffers::memory_bytes() const {
    std::size_t bytes = 0;
    for (const gl::Buffer* b : std::initializer_list<const gl::Buffer*>{&pillars_, &corner_depths_, &cells_, &values_, &cell_face_classes_, &primary_bits_,
                                &secondary_.buffer, &primary_.buffer, &primary_cells_.buffer, &shell_.buffer, &outer_.buffer, &all_.buffer})
        bytes += b->size_bytes();
    return bytes;
}

void GridBuffers::set_values(const std::vector<float>& compact_values) {
    glNamedBufferSubData(values_.id(), 0, GLsizeiptr(compact_values.size() * sizeof(float)), compact_values.data());
}

void GridBuffers::upload_primary_bits(const std::vector<std::uint32_t>& bits) {
    glNamedBufferSubData(primary_bits_.id(), 0, GLsizeiptr(std::min(bits.size() * 4, primary_bits_.size_bytes())),
                         bits.data());
}

std::vector<std::uint32_t> GridBuffers::read_primary_bits() const {
    std::vector<std::uint32_t> bits((layout_.cells.size() + 31) / 32);
    glGetNamedBufferSubData(primary_bits_.id(), 0, GLsizeiptr(bits.size() * 4), bits.data());
    return bits;
}

namespace {
void resize_list(FaceBuffer& list, std::size_t count) {
    if (list.buffer.size_bytes() < count * sizeof(std::uint32_t) || !list.buffer)
        list.buffer = gl::Buffer(std::max<std::size_t>(count, 1) * sizeof(std::uint32_t), nullptr);
    list.count = count;
}
}  // namespace

void GridBuffers::resize_primary_lists(std::size_t cells, std::size_t faces) {
    resize_list(primary_cells_, cells);
    resize_list(primary_, faces);
}

void GridBuffers::bind_geometry() const {
    pillar_texels_.bind(pillar_texture_unit);
    corner_depth_texels_.bind(corner_depth_texture_unit);
    cell_texels_.bind(cell_texture_unit);
    value_texels_.bind(value_texture_unit);
}

void GridBuffers::bind_culling_inputs() const {
    cell_face_classes_.bind_base(GL_SHADER_STORAGE_BUFFER, cell_face_classes_binding);
    primary_bits_.bind_base(GL_SHADER_STORAGE_BUFFER, primary_bits_binding);
}

void GridBuffers::draw_faces(const FaceBuffer& faces) {
    if (faces.count == 0) return;
    // gl_VertexID / 6 indexes the bound range; chunks of 2^27 faces keep 6 x count within GLsizei.
    constexpr std::size_t chunk_faces = std::size_t(1) << 27;
    for (std::size_t first = 0; first < faces.count; first += chunk_faces) {
        const std::size_t count = std::min(chunk_faces, faces.count - first);
        glBindBufferRange(GL_SHADER_STORAGE_BUFFER, faces_binding, faces.buffer.id(), GLintptr(first * 4), GLsizeiptr(count * 4));
        glDrawArrays(GL_TRIANGLES, 0, GLsizei(6 * count));
    }
}

}  // namespace cutaway::pipeline

#include "cutaway/grid_buffers.h"

#include <algorithm>
#include <span>
#include <stdexcept>
#include <string>

#include "gl/face_culling.h"
#include "gl/uniforms.h"
#include "grid/enclosed_pockets.h"

namespace cutaway::pipeline {

FaceBuffer FaceBuffer::from(const std::vector<std::uint32_t>& records) {
    return {gl::Buffer::from(std::span<const std::uint32_t>(records)), records.size()};
}

WoundFaces WoundFaces::from(const std::vector<std::uint32_t>& records, const GridLayout& layout) {
    std::vector<std::uint32_t> counter_clockwise, clockwise;
    for (std::uint32_t record : records) {
        (layout.inward_corner_order(face_record_cell(record)) ? clockwise : counter_clockwise).push_back(record);
    }
    return {FaceBuffer::from(counter_clockwise), FaceBuffer::from(clockwise)};
}

namespace {
/// The layout's outer faces, split by winding.
WoundFaces outer_surface(const GridLayout& layout, const grid::ZcornStore& zcorn) {
    const std::vector<bool> active = active_cells(layout, zcorn.dims());
    return WoundFaces::from(outer_faces(layout, zcorn, active, grid::enclosed_inactive_cells(zcorn, active, layout.face_tolerance)),
                            layout);
}

/// The layout's packed classes (2 bits per side), 16 bits per active cell as the shaders read them
/// (an R16UI buffer texture; the selection's storage buffer reads two cells per word, so the
/// count is padded to even).
std::vector<std::uint16_t> packed_face_classes(const GridLayout& layout) {
    std::vector<std::uint16_t> classes(layout.face_classes.size() + layout.face_classes.size() % 2, 0);
    std::copy(layout.face_classes.begin(), layout.face_classes.end(), classes.begin());
    return classes;
}
/// Corner-plane slots per layer: 1 when compact (shared layer interfaces), 2 otherwise.
unsigned slots_per_layer(const grid::ZcornStore& zcorn) { return zcorn.is_compact() ? 1u : 2u; }

/// Depth plane slots of the corner-plane texels: the store's own (ZcornStore), NZ+1 when compact
/// (a layer's bottom is the next layer's top), 2NZ otherwise.
std::size_t corner_plane_slots(const grid::ZcornStore& zcorn) {
    const int nz = zcorn.dims().nz;
    return std::size_t(zcorn.is_compact() ? nz + 1 : 2 * nz);
}

/// Per active cell as the shaders read it (common/grid.glsl), two words: the pillar index of its
/// corner 0 (bits 0-30) with the flip bit of GridLayout::cells (bit 31), and the corner-plane texel
/// of its top face (its bottom face's is one slot, NX * NY texels, further).
std::vector<std::uint32_t> gpu_cell_records(const GridLayout& layout, const grid::ZcornStore& zcorn) {
    const grid::GridDims& dims = zcorn.dims();
    const std::size_t nx = std::size_t(dims.nx), ny = std::size_t(dims.ny);
    const std::size_t layer_slots = slots_per_layer(zcorn);
    std::vector<std::uint32_t> records(2 * layout.cells.size());
    const std::ptrdiff_t count = std::ptrdiff_t(layout.cells.size());
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t index = 0; index < count; ++index) {
        const std::size_t c = std::size_t(index);
        const std::size_t eclipse = layout.cells[c] & 0x7fffffffu;
        const std::size_t i = eclipse % nx, j = eclipse / nx % ny, k = eclipse / (nx * ny);
        records[2 * c] = std::uint32_t(j * (nx + 1) + i) | (layout.cells[c] & 0x80000000u);
        records[2 * c + 1] = std::uint32_t((layer_slots * k * ny + j) * nx + i);
    }
    return records;
}

/// ZCORN as the shaders read it: one RGBA32F texel per depth plane slot and cell column (i, j),
/// slot-major then j, i, holding the depths of the column's 4 corners in that plane (component
/// bit 0: i+1, bit 1: j+1), centred model units. Filled a slot at a time, so the CPU never holds
/// more than one plane. Shared layer interfaces are stored once (16 bytes per cell for a compact
/// ZCORN instead of 32 for 8 depths per cell) and the texel count stays within the GL limit up
/// to ~134M cells. Throws std::invalid_argument when it does not.
gl::Buffer upload_corner_planes(const grid::ZcornStore& zcorn, double centre_z) {
    const grid::GridDims& dims = zcorn.dims();
    const std::size_t slots = corner_plane_slots(zcorn), columns = std::size_t(dims.nx) * std::size_t(dims.ny);
    GLint64 max_texels = 0;
    glGetInteger64v(GL_MAX_TEXTURE_BUFFER_SIZE, &max_texels);
    if (slots * columns > std::size_t(max_texels))
        throw std::invalid_argument("model of " + std::to_string(dims.nx) + "x" + std::to_string(dims.ny) + "x" +
                                    std::to_string(dims.nz) + " cells needs " + std::to_string(slots * columns) +
                                    " corner-plane texels (" + (zcorn.is_compact() ? "compact" : "full") +
                                    " ZCORN); GL_MAX_TEXTURE_BUFFER_SIZE is " + std::to_string(max_texels));
    const std::size_t slot_bytes = 4 * columns * sizeof(float);
    gl::Buffer buffer(slots * slot_bytes, nullptr, GL_DYNAMIC_STORAGE_BIT);
    std::vector<float> plane(4 * columns);
    for (std::size_t s = 0; s < slots; ++s) {
        // Compact: slot s < NZ is layer s's top, slot NZ the last layer's bottom. Full: slot 2k + b.
        const bool compact = zcorn.is_compact();
        const int k = compact ? int(std::min<std::size_t>(s, std::size_t(dims.nz - 1))) : int(s / 2);
        const int bottom = (compact ? s == std::size_t(dims.nz) : s % 2 == 1) ? 4 : 0;
#pragma omp parallel for schedule(static)
        for (int j = 0; j < dims.ny; ++j)
            for (int i = 0; i < dims.nx; ++i)
                for (int c = 0; c < 4; ++c)
                    plane[4 * (std::size_t(j) * std::size_t(dims.nx) + std::size_t(i)) + std::size_t(c)] =
                        float(zcorn.corner_depth(i, j, k, c | bottom) - centre_z);
        glNamedBufferSubData(buffer.id(), GLintptr(s * slot_bytes), GLsizeiptr(slot_bytes), plane.data());
    }
    return buffer;
}
}  // namespace

GridBuffers::GridBuffers(const GridLayout& layout, const grid::ZcornStore& zcorn, const ModelFrame& frame)
    : layout_(layout),
      grid_size_(unsigned(zcorn.dims().nx), unsigned(zcorn.dims().ny)),
      plane_slots_per_layer_(slots_per_layer(zcorn)),
      frame_(frame),
      pillars_(gl::Buffer::from(std::span<const float>(layout.pillars))),
      corner_planes_(upload_corner_planes(zcorn, frame.centre.z)),
      cells_(gl::Buffer::from(std::span<const std::uint32_t>(gpu_cell_records(layout, zcorn)))),
      values_(layout.cells.size() * sizeof(float), nullptr, GL_DYNAMIC_STORAGE_BIT),
      cell_face_classes_(gl::Buffer::from(std::span<const std::uint16_t>(packed_face_classes(layout)))),
      primary_bits_((layout.cells.size() + 31) / 32 * sizeof(std::uint32_t) + sizeof(std::uint32_t), nullptr,
                    GL_DYNAMIC_STORAGE_BIT),
      outer_(outer_surface(layout, zcorn)),
      pillar_texels_(pillars_, GL_RGBA32F),
      corner_plane_texels_(corner_planes_, GL_RGBA32F),
      cell_texels_(cells_, GL_RG32UI),
      value_texels_(values_, GL_R32F),
      value16_texels_(values_, GL_R16, std::max<std::size_t>(layout.cells.size(), 1) * sizeof(std::uint16_t)),
      face_class_texels_(cell_face_classes_, GL_R16UI),
      primary_bit_texels_(primary_bits_, GL_R32UI) {}

const FaceBuffer& GridBuffers::all_faces() const {
    if (!all_.buffer) all_ = FaceBuffer::from(pipeline::all_faces(layout_));
    return all_;
}

void GridBuffers::set_geometry_uniforms(const gl::Program& program) const {
    gl::set_uniform(program, "grid_size", grid_size_);
    gl::set_uniform(program, "up_sign", float(frame_.up_sign));
    gl::set_uniform(program, "z_scale", float(frame_.z_scale));
    gl::set_uniform(program, "value_decoding", value_decoding_);
}

std::size_t GridBuffers::memory_bytes() const {
    std::size_t bytes = 0;
    for (const gl::Buffer* b : std::initializer_list<const gl::Buffer*>{&pillars_, &corner_planes_, &cells_, &values_, &cell_face_classes_, &primary_bits_,
                                &secondary_.buffer, &primary_.buffer, &primary_cells_.buffer, &outer_.counter_clockwise.buffer, &outer_.clockwise.buffer, &all_.buffer})
        bytes += b->size_bytes();
    return bytes;
}

void GridBuffers::set_values(const std::vector<float>& compact_values) {
    glNamedBufferSubData(values_.id(), 0, GLsizeiptr(compact_values.size() * sizeof(float)), compact_values.data());
    value_decoding_ = glm::vec2(0, 1);
    values_quantised_ = false;
}

void GridBuffers::set_values(const QuantisedValues& compact_values) {
    const std::vector<std::uint16_t>& codes = compact_values.codes;
    glNamedBufferSubData(values_.id(), 0, GLsizeiptr(codes.size() * sizeof(std::uint16_t)), codes.data());
    value_decoding_ = glm::vec2(compact_values.offset, compact_values.span);  // span 0: every value the offset
    values_quantised_ = true;
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
    corner_plane_texels_.bind(corner_depth_texture_unit);
    cell_texels_.bind(cell_texture_unit);
    (values_quantised() ? value16_texels_ : value_texels_).bind(value_texture_unit);
}

void GridBuffers::bind_culling_inputs() const {
    cell_face_classes_.bind_base(GL_SHADER_STORAGE_BUFFER, cell_face_classes_binding);
    primary_bits_.bind_base(GL_SHADER_STORAGE_BUFFER, primary_bits_binding);
    face_class_texels_.bind(face_class_texture_unit);
    primary_bit_texels_.bind(primary_bit_texture_unit);
}

void GridBuffers::draw_faces(const FaceBuffer& faces) const {
    if (faces.count == 0) return;
    // gl_VertexID / 4 indexes the bound range; ranges of 2^27 faces keep 4 x count within GLint.
    constexpr std::size_t range_faces = std::size_t(1) << 27;
    for (std::size_t first = 0; first < faces.count; first += range_faces) {
        const std::size_t count = std::min(range_faces, faces.count - first);
        glBindBufferRange(GL_SHADER_STORAGE_BUFFER, faces_binding, faces.buffer.id(), GLintptr(first * 4), GLsizeiptr(count * 4));
        quads_.draw(count);
    }
}

void GridBuffers::draw_faces(const WoundFaces& faces, GLenum culled) const {
    const gl::FaceCulling culling(culled);
    for (const auto& [part, front] : {std::pair{&faces.counter_clockwise, GL_CCW}, std::pair{&faces.clockwise, GL_CW}}) {
        glFrontFace(front);
        draw_faces(*part);
    }
}

}  // namespace cutaway::pipeline

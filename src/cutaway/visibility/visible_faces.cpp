#include "cutaway/visibility/visible_faces.h"

#include <algorithm>
#include <array>
#include <span>

#include "common/shared_constants.h"
#include "gl/compute_dispatch.h"
#include "gl/uniforms.h"

namespace cutaway::pipeline {
namespace {

enum CullingBinding : unsigned {
    brick_begin_binding = shared::ssbo_brick_begin, brick_boxes_binding = shared::ssbo_brick_boxes,
    culling_binding = shared::ssbo_culling_counters, visible_faces_binding = shared::ssbo_visible_faces,
    draw_commands_binding = shared::ssbo_draw_commands, brick_classes_binding = shared::ssbo_brick_classes,
    cell_masks_binding = shared::ssbo_cell_face_masks, brick_counts_binding = shared::ssbo_brick_face_counts,
    brick_offsets_binding = shared::ssbo_brick_offsets, block_offsets_binding = shared::ssbo_block_offsets };
/// Texture units of cull_cells.comp's buffer textures (the grid's own take 8-13).
enum CullingTextureUnit : unsigned { brick_cell_texture_unit = shared::tex_brick_cells,
                                     brick_begin_texture_unit = shared::tex_brick_begin,
                                     brick_class_texture_unit = shared::tex_brick_classes };

/// Bricks one workgroup of cull_cells.comp takes in turn: on llvmpipe a workgroup costs a fixed
/// start-up before its first instruction (an empty dispatch of one-brick groups is measurable
/// against the whole selection), so a group per brick cost more than the selection; 16 leaves
/// hundreds of groups on sapphire, plenty for any number of threads.
constexpr unsigned bricks_per_group = 16;

/// The uniforms of visibility/classify.glsl.
/// The classification's own uniforms (its cameras are the bound blocks, common/cameras.glsl).
void set_classification_uniforms(const gl::Program& p, const CutTargets* cut, bool keep_rear_faces) {
    gl::set_uniform(p, "has_cut", cut != nullptr);
    gl::set_uniform(p, "keep_rear_faces", keep_rear_faces);
    gl::set_uniform(p, "cut_surface", 0);
}

/// Bricks one invocation of visibility/scan_bricks.comp sums in turn (the block totals are then
/// summed by one invocation: 1,420 blocks for scale-100m's 1.45M bricks).
constexpr unsigned scan_block = 1024;

/// Runs `p` (local size 64) over `invocations`, then waits for its writes as `barrier` says.
void dispatch_invocations(const gl::Program& p, std::size_t invocations, GLbitfield barrier = GL_SHADER_STORAGE_BARRIER_BIT) {
    p.use();
    const auto [x, y] = gl::dispatch_grid((invocations + 63) / 64);
    glDispatchCompute(x, y, 1);
    glMemoryBarrier(barrier);
}

/// The counters of visibility/cull_cells.comp.
constexpr std::array<std::uint32_t, 5> cleared_counters{0, 0, 0, 0, 0};
/// Byte offset of faces_requested in visibility/culling_counters.glsl.
constexpr GLintptr faces_requested_offset = 4 * sizeof(std::uint32_t);
/// DrawElementsIndirectCommand: count, instance count, first index, base vertex, base instance.
constexpr std::size_t draw_command_bytes = 5 * sizeof(std::uint32_t);

}  // namespace

VisibleFaces::VisibleFaces(const gl::ShaderLibrary& shaders, const CellBricks& bricks, std::size_t face_limit,
                           std::size_t initial_capacity)
    : classify_(shaders, {{GL_COMPUTE_SHADER, "visibility/classify_bricks.comp"}}),
      cull_(shaders, {{GL_COMPUTE_SHADER, "visibility/cull_cells.comp"}}),
      finish_(shaders.build({{GL_COMPUTE_SHADER, "visibility/finish_culling.comp"}})),
      scan_bricks_(shaders.build({{GL_COMPUTE_SHADER, "visibility/scan_bricks.comp"}})),
      scan_blocks_(shaders.build({{GL_COMPUTE_SHADER, "visibility/scan_bricks.comp"}}, {{"BLOCKS", ""}})),
      write_faces_(shaders.build({{GL_COMPUTE_SHADER, "visibility/write_visible_faces.comp"}})),
      pyramid_(shaders),
      brick_cells_(gl::Buffer::from(std::span<const std::uint32_t>(bricks.cells))),
      brick_begin_(gl::Buffer::from(std::span<const std::uint32_t>(bricks.begin))),
      brick_boxes_(gl::Buffer::from(std::span<const float>(bricks.boxes))),
      brick_classes_(std::max<std::size_t>(bricks.brick_count(), 1) * sizeof(std::uint32_t), nullptr),
      brick_cell_texels_(brick_cells_, GL_R32UI),
      brick_begin_texels_(brick_begin_, GL_R32UI),
      brick_class_texels_(brick_classes_, GL_R32UI),
      brick_count_(bricks.brick_count()),
      face_limit_(std::max<std::size_t>(face_limit, 1)),
      counters_(sizeof(cleared_counters), cleared_counters.data(), GL_DYNAMIC_STORAGE_BIT),
      cell_masks_(std::max<std::size_t>((bricks.cells.size() + 3) / 4, 1) * sizeof(std::uint32_t), nullptr),
      brick_counts_(std::max<std::size_t>(brick_count_, 1) * sizeof(std::uint32_t), nullptr),
      brick_offsets_(std::max<std::size_t>(brick_count_, 1) * sizeof(std::uint32_t), nullptr),
      block_offsets_(std::max<std::size_t>((brick_count_ + scan_block - 1) / scan_block, 1) * sizeof(std::uint32_t), nullptr) {
    set_capacity(initial_capacity);
}

void VisibleFaces::set_capacity(std::size_t faces) {
    face_capacity_ = std::clamp<std::size_t>(faces, 1, face_limit_);
    faces_ = {};  // the old buffer goes before the new one is allocated
    faces_ = gl::Buffer(face_capacity_ * sizeof(std::uint32_t), nullptr);
    chunks_ = QuadDraw::chunks_for(face_capacity_);
    commands_ = gl::Buffer(chunks_ * draw_command_bytes, nullptr);
}

bool VisibleFaces::grow_to_fit() {
    if (face_capacity_ == face_limit_) return false;  // sized ahead of time: nothing to read back
    std::uint32_t requested = 0;
    glGetNamedBufferSubData(counters_.id(), faces_requested_offset, sizeof(requested), &requested);
    count_readback_bytes_ += sizeof(requested);
    if (requested <= face_capacity_) return false;
    // A margin of an eighth, so that a camera moving on does not grow the buffer every frame.
    set_capacity(std::size_t(requested) + std::size_t(requested) / 8);
    return true;
}

void VisibleFaces::select(const GridBuffers& grid, const CameraBlocks& cameras, const Camera& camera, const CutTargets* cut,
                          const Camera& cut_camera, bool keep_rear_faces) {
    cameras.bind_view(camera);
    cameras.bind_cut(cut_camera);
    if (cut) pyramid_.build(cut->surface);
    glNamedBufferSubData(counters_.id(), 0, sizeof(cleared_counters), cleared_counters.data());
    for (const gl::Buffer* cleared : {&cell_masks_, &brick_counts_})
        glClearNamedBufferData(cleared->id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
    if (cut) cut->surface.bind(0);
    brick_begin_.bind_base(GL_SHADER_STORAGE_BUFFER, brick_begin_binding);
    brick_boxes_.bind_base(GL_SHADER_STORAGE_BUFFER, brick_boxes_binding);
    brick_classes_.bind_base(GL_SHADER_STORAGE_BUFFER, brick_classes_binding);
    counters_.bind_base(GL_SHADER_STORAGE_BUFFER, culling_binding);

    const gl::ShaderDefines defines =
        same_view(camera, cut_camera) ? gl::ShaderDefines{{"CUT_CAMERA_IS_VIEW", ""}} : gl::ShaderDefines{};
    const gl::Program& classify = classify_.get(defines);
    set_classification_uniforms(classify, cut, keep_rear_faces);
    gl::set_uniform(classify, "brick_count", unsigned(brick_count_));
    pyramid_.bind_for(classify);
    dispatch_invocations(classify, brick_count_, GL_TEXTURE_FETCH_BARRIER_BIT);

    const gl::Program& p = cull_.get(defines);
    set_classification_uniforms(p, cut, keep_rear_faces);
    gl::set_uniform(p, "grid_size", grid.grid_size());
    gl::set_uniform(p, "up_sign", float(grid.frame().up_sign));
    gl::set_uniform(p, "z_scale", float(grid.frame().z_scale));
    gl::set_uniform(p, "brick_count", unsigned(brick_count_));
    gl::set_uniform(p, "bricks_per_group", bricks_per_group);
    pyramid_.bind_for(p);
    grid.bind_geometry();
    grid.bind_culling_inputs();
    brick_cell_texels_.bind(brick_cell_texture_unit);
    brick_begin_texels_.bind(brick_begin_texture_unit);
    brick_class_texels_.bind(brick_class_texture_unit);
    cell_masks_.bind_base(GL_SHADER_STORAGE_BUFFER, cell_masks_binding);
    brick_counts_.bind_base(GL_SHADER_STORAGE_BUFFER, brick_counts_binding);
    p.use();
    const auto [groups_x, groups_y] = gl::dispatch_grid((brick_count_ + bricks_per_group - 1) / bricks_per_group);
    glDispatchCompute(groups_x, groups_y, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    write_in_brick_order(grid);
    gl::set_uniform(finish_, "face_capacity", unsigned(face_capacity_));
    gl::set_uniform(finish_, "chunk_count", unsigned(chunks_));
    gl::set_uniform(finish_, "quads_per_chunk", QuadDraw::quads_per_chunk);
    commands_.bind_base(GL_SHADER_STORAGE_BUFFER, draw_commands_binding);
    finish_.use();
    glDispatchCompute(GLuint((chunks_ + 63) / 64), 1, 1);
    glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
}

void VisibleFaces::write_in_brick_order(const GridBuffers& grid) {
    brick_offsets_.bind_base(GL_SHADER_STORAGE_BUFFER, brick_offsets_binding);
    block_offsets_.bind_base(GL_SHADER_STORAGE_BUFFER, block_offsets_binding);
    const std::size_t blocks = (brick_count_ + scan_block - 1) / scan_block;
    gl::set_uniform(scan_bricks_, "scan_block", scan_block);
    gl::set_uniform(scan_bricks_, "brick_count", unsigned(brick_count_));
    dispatch_invocations(scan_bricks_, blocks);
    gl::set_uniform(scan_blocks_, "scan_block", scan_block);
    gl::set_uniform(scan_blocks_, "block_count", unsigned(blocks));
    dispatch_invocations(scan_blocks_, 1);

    const gl::Program& w = write_faces_;
    gl::set_uniform(w, "brick_count", unsigned(brick_count_));
    gl::set_uniform(w, "scan_block", scan_block);
    gl::set_uniform(w, "face_capacity", unsigned(face_capacity_));
    grid.bind_culling_inputs();
    brick_cell_texels_.bind(brick_cell_texture_unit);
    brick_begin_texels_.bind(brick_begin_texture_unit);
    faces_.bind_base(GL_SHADER_STORAGE_BUFFER, visible_faces_binding);
    dispatch_invocations(w, brick_count_);
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

std::vector<std::uint32_t> VisibleFaces::read_faces() const {
    std::vector<std::uint32_t> records(read_counts().faces);
    glGetNamedBufferSubData(faces_.id(), 0, GLsizeiptr(records.size() * sizeof(std::uint32_t)), records.data());
    return records;
}

std::size_t VisibleFaces::memory_bytes() const {
    return brick_cells_.size_bytes() + brick_begin_.size_bytes() + brick_boxes_.size_bytes() + brick_classes_.size_bytes() + faces_.size_bytes() +
           counters_.size_bytes() + commands_.size_bytes() + cell_masks_.size_bytes() + brick_counts_.size_bytes() +
           brick_offsets_.size_bytes() + block_offsets_.size_bytes() + pyramid_.memory_bytes();
}

}  // namespace cutaway::pipeline

#include "cutaway/selection/gpu_primary_selection.h"

#include <algorithm>
#include <limits>
#include <span>
#include <stdexcept>

#include "common/shared_constants.h"
#include "gl/uniforms.h"

namespace cutaway::pipeline {
namespace {

enum SelectionBinding : unsigned {
    active_words_binding = shared::ssbo_active_words, word_counts_binding = shared::ssbo_word_counts,
    totals_binding = shared::ssbo_selection_totals, primary_cells_out_binding = shared::ssbo_primary_cells_out,
    primary_faces_out_binding = shared::ssbo_primary_faces_out };

std::size_t word_count(std::size_t cells) { return (cells + 31) / 32; }

/// Per word of 32 Eclipse cells: its active bits and the number of active cells before it, so
/// primary_words.glsl finds an active cell's compact index (its rank in Eclipse order) as that
/// count plus the active bits below it: 8 bytes per 32 cells instead of 4 bytes per cell.
/// The compact indices are these ranks (grid_layout.h).
std::vector<std::uint32_t> active_words(const std::vector<std::uint8_t>& actnum) {
    std::vector<std::uint32_t> words(2 * std::max<std::size_t>(word_count(actnum.size()), 1), 0);
    std::uint32_t active = 0;
    for (std::size_t cell = 0; cell < actnum.size(); ++cell) {
        if (cell % 32 == 0) words[2 * (cell / 32) + 1] = active;
        if (actnum[cell] == 0) continue;
        words[2 * (cell / 32)] |= 1u << (cell % 32);
        ++active;
    }
    return words;
}

}  // namespace

GpuPrimarySelection::GpuPrimarySelection(const gl::ShaderLibrary& shaders, const GridLayout& layout,
                                         const grid::CornerPointGrid& grid)
    : mark_(shaders.build({{GL_COMPUTE_SHADER, "selection/mark_primaries.comp"}})),
      count_(shaders.build({{GL_COMPUTE_SHADER, "selection/count_primary_lists.comp"}})),
      scan_(shaders.build({{GL_COMPUTE_SHADER, "selection/scan_primary_counts.comp"}})),
      write_(shaders.build({{GL_COMPUTE_SHADER, "selection/write_primary_lists.comp"}})),
      active_cells_(layout.cells.size()),
      dims_(unsigned(grid.dims().nx), unsigned(grid.dims().ny), unsigned(grid.dims().nz)),
      active_words_(gl::Buffer::from(std::span<const std::uint32_t>(active_words(grid.actnum())))),
      word_counts_(std::max<std::size_t>(word_count(active_cells_), 1) * 2 * sizeof(std::uint32_t), nullptr),
      totals_(2 * sizeof(std::uint32_t), nullptr) {
    for (const gl::Program* p : {&mark_, &count_, &write_}) {
        gl::set_uniform(*p, "active_cells", unsigned(active_cells_));
        gl::set_uniform(*p, "grid_dims", dims_);
    }
    gl::set_uniform(scan_, "word_total", unsigned(word_count(active_cells_)));
}

void GpuPrimarySelection::bind_inputs(const GridBuffers& grid) const {
    grid.bind_geometry();
    grid.bind_culling_inputs();
    // A cell's IJK comes from its top-face texel in the grid's cell records (primary_words.glsl).
    for (const gl::Program* p : {&mark_, &count_, &write_})
        gl::set_uniform(*p, "plane_slots_per_layer", grid.plane_slots_per_layer());
    active_words_.bind_base(GL_SHADER_STORAGE_BUFFER, active_words_binding);
    word_counts_.bind_base(GL_SHADER_STORAGE_BUFFER, word_counts_binding);
}

void GpuPrimarySelection::dispatch_words(const gl::Program& program) const {
    // 64 words per workgroup, spread over Y beyond the 65535 groups GL guarantees along X.
    const std::size_t groups = std::max<std::size_t>((word_count(active_cells_) + 63) / 64, 1);
    const std::size_t groups_x = std::min<std::size_t>(groups, 65535);
    program.use();
    glDispatchCompute(GLuint(groups_x), GLuint((groups + groups_x - 1) / groups_x), 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void GpuPrimarySelection::select_range(GridBuffers& grid, const grid::PrimaryRange& range,
                                       const std::optional<grid::IjkBox>& box) {
    gl::set_uniform(mark_, "value_range", glm::vec2(range.min, range.max));
    gl::set_uniform(mark_, "use_box", box.has_value());
    if (box) {
        gl::set_uniform(mark_, "box_min", glm::ivec3(box->i0, box->j0, box->k0));
        gl::set_uniform(mark_, "box_max", glm::ivec3(box->i1, box->j1, box->k1));
    }
    bind_inputs(grid);
    dispatch_words(mark_);
    build_lists(grid);
}

void GpuPrimarySelection::select_bits(GridBuffers& grid, const std::vector<std::uint32_t>& bits) {
    if (bits.size() != word_count(active_cells_))
        throw std::invalid_argument("primary bits: " + std::to_string(bits.size()) + " words, expected " +
                                    std::to_string(word_count(active_cells_)));
    grid.upload_primary_bits(bits);
    bind_inputs(grid);
    build_lists(grid);
}

void GpuPrimarySelection::build_lists(GridBuffers& grid) {
    dispatch_words(count_);
    totals_.bind_base(GL_SHADER_STORAGE_BUFFER, totals_binding);
    scan_.use();
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    std::uint32_t totals[2] = {0, 0};
    glGetNamedBufferSubData(totals_.id(), 0, sizeof(totals), totals);
    grid.resize_primary_lists(totals[0], totals[1]);
    grid.primary_cells().buffer.bind_base(GL_SHADER_STORAGE_BUFFER, primary_cells_out_binding);
    grid.primary_faces().buffer.bind_base(GL_SHADER_STORAGE_BUFFER, primary_faces_out_binding);
    dispatch_words(write_);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT);
}

std::size_t GpuPrimarySelection::memory_bytes() const {
    return active_words_.size_bytes() + word_counts_.size_bytes() +
           totals_.size_bytes();
}

std::vector<std::uint32_t> primary_bits(const GridLayout& layout, const std::vector<std::uint8_t>& flags) {
    std::vector<std::uint32_t> bits(word_count(layout.cells.size()), 0);
    for (std::size_t c = 0; c < layout.cells.size(); ++c)
        if (flags.at(layout.cells[c] & 0x7fffffffu) != 0) bits[c / 32] |= 1u << (c % 32);
    return bits;
}

std::vector<std::uint8_t> primary_flags(const GridLayout& layout, const std::vector<std::uint32_t>& bits,
                                        std::size_t cell_count) {
    std::vector<std::uint8_t> flags(cell_count, 0);
    for (std::size_t c = 0; c < layout.cells.size(); ++c)
        if ((bits.at(c / 32) >> (c % 32)) & 1u) flags[layout.cells[c] & 0x7fffffffu] = 1;
    return flags;
}

}  // namespace cutaway::pipeline

#pragma once
// The primary set chosen on the GPU (shaders/selection/): from the property range (and an IJK
// box) over the values already uploaded for colouring, or from given bits. A range change
// uploads nothing; only the two list lengths are read back (8 bytes), to size the lists.
// The lists come out in build_face_lists' order, so they equal the CPU reference exactly.
#include <cstdint>
#include <optional>
#include <vector>

#include "cutaway/grid_buffers.h"
#include "cutaway/grid_layout.h"
#include "gl/shader_library.h"
#include "grid/primary_selection.h"

namespace cutaway::pipeline {

class GpuPrimarySelection {
public:
    /// `layout` of `grid` (its dimensions and ACTNUM are read here).
    GpuPrimarySelection(const gl::ShaderLibrary& shaders, const GridLayout& layout, const grid::CornerPointGrid& grid);

    /// Primaries: active cells whose value (GridBuffers::set_values) lies in `range`, inside `box`.
    void select_range(GridBuffers& grid, const grid::PrimaryRange& range, const std::optional<grid::IjkBox>& box);
    /// Primaries given as one bit per compact cell (bit c % 32 of word c / 32).
    void select_bits(GridBuffers& grid, const std::vector<std::uint32_t>& bits);
    std::size_t memory_bytes() const;

private:
    /// Counts, scans and writes the primary cell and face lists from the bits on the GPU (inputs bound).
    void build_lists(GridBuffers& grid);
    void bind_inputs(const GridBuffers& grid) const;
    void dispatch_words(const gl::Program& program) const;

    gl::Program mark_, count_, scan_, write_;
    std::size_t active_cells_ = 0;
    glm::uvec3 dims_;
    gl::Buffer active_words_, word_counts_, totals_;
};

/// One bit per compact cell of `layout` from per-Eclipse-cell flags.
std::vector<std::uint32_t> primary_bits(const GridLayout& layout, const std::vector<std::uint8_t>& flags);
/// One flag per Eclipse cell (`cell_count`) from the bits of `layout`'s compact cells.
std::vector<std::uint8_t> primary_flags(const GridLayout& layout, const std::vector<std::uint32_t>& bits,
                                        std::size_t cell_count);

}  // namespace cutaway::pipeline

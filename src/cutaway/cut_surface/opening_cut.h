#pragma once
// The cut of cells that smooth coherence opens or closes over an animation's frames
// (temporal/cell_openings.h): each such cell's box (cell_boxes.h) with its back face part of the
// way from where its view rays enter the model's bounds (it cuts nothing there) to the cell's rear. The
// seed strategies (cut_seeds.h) take the back faces as seeds beside the primaries', so the cut
// opens with the strategy's own walls and, at the full opening, is the strategy's cut of the cell
// as a primary; for the others the frustum is drawn into the cut's depth after the strategy's cut
// with the same max (GL_GREATER), as the cut volumes are. Everything downstream reads one cut.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "cutaway/cut_surface/cut_surface_strategy.h"
#include "cutaway/frame_targets.h"
#include "cutaway/model_frame.h"
#include "gl/gl_objects.h"
#include "gl/shader_library.h"

namespace cutaway::pipeline {

/// An active cell by compact index and how far its cut reaches, in [0, 1]: from where its view
/// rays enter the model, or beside the cut from its own wall drop (the depth a wall of the cut
/// falls over the cell's width: the neighbours' cut reaches that far over the cell already).
struct CompactOpening {
    std::uint32_t compact_cell = 0;
    float opening = 0;
    bool beside_cut = false;
};

class OpeningCut {
public:
    /// `frame`: the model's render-space bounds, where the cells' view rays enter the model.
    OpeningCut(const gl::ShaderLibrary& shaders, const ModelFrame& frame);

    /// Replaces the opening cells (8 bytes each uploaded); an empty list removes them.
    void set_cells(const std::vector<CompactOpening>& cells);
    bool empty() const { return count_ == 0; }
    std::size_t cell_count() const { return count_; }
    std::size_t memory_bytes() const { return cells_.size_bytes(); }

    /// Draws the cells' frustums into targets' depth (holding the strategy's cut, or cleared).
    void draw(const CutSurfaceInputs& inputs, const CutTargets& targets) const;
    /// Draws the cells' back faces into a seed image's framebuffer (cut_seeds.h): GL_GREATER.
    void draw_seeds(const CutSurfaceInputs& inputs, const gl::Framebuffer& seeds) const;

private:
    gl::Program program_;
    gl::Program seed_program_;
    gl::Buffer cells_;  ///< compact cell, opening's float bits
    std::size_t count_ = 0;
};

}  // namespace cutaway::pipeline

#pragma once
// Draws one point per primary cell through the frustum shaders (cut_surface/frustum.*): the cell's
// box in the cut camera's perspective-divided (u, v, s) space, its back face pushed back by the
// margin and widened by one pixel, plus the walls unless the program was built with
// BACK_FACE_ONLY. Shared by the frustum union and the cone-field seeds, so both see the same boxes.
#include "cutaway/cut_surface/cut_surface_strategy.h"
#include "gl/gl_objects.h"

namespace cutaway::pipeline {

/// Variants of the frustum program.
struct CellBoxProgramOptions {
    bool back_face_only = false;       ///< BACK_FACE_ONLY: seeds
    bool clusters = false;             ///< CLUSTERS: one box per cluster of cells (ClusterBoxes), not per primary
    bool constant_wall_slope = false;  ///< CONSTANT_WALL_SLOPE: uniform wall_u_per_depth for every wall
    bool opening = false;              ///< OPENING: cells with how far their cut reaches (OpeningBoxes)
};

/// The frustum program: frustum.vert/.geom/.frag with the variant's defines.
gl::Program build_cell_box_program(const gl::ShaderLibrary& shaders, const CellBoxProgramOptions& options);

/// Boxes over clusters of cells (a program built with `clusters`): buffer textures of (first,
/// count) per cluster (GL_RG32UI) and of the clusters' compact cells (GL_R32UI).
struct ClusterBoxes {
    const gl::BufferTexture& ranges;
    const gl::BufferTexture& cells;
    std::size_t count = 0;
};

/// Cells whose cut reaches part of the way to them (a program built with `opening`): per cell its
/// compact index and the share reached as float bits (two uint32 each, std430).
struct OpeningBoxes {
    const gl::Buffer& cells;
    std::size_t count = 0;
};

/// Sets the program's uniforms from `inputs` and draws every primary cell (or every cluster of
/// `clusters`) into `framebuffer` (depth only, GL_GREATER: the framebuffer keeps the farthest
/// hull; the caller clears it to 0). Leaves the depth function at GL_LESS. No-op without boxes.
void draw_cell_boxes(const gl::Program& program, const CutSurfaceInputs& inputs, const gl::Framebuffer& framebuffer,
                     const ClusterBoxes* clusters = nullptr);
/// As draw_cell_boxes, for the opening cells of `boxes` (a program built with `opening`).
void draw_opening_boxes(const gl::Program& program, const CutSurfaceInputs& inputs, const gl::Framebuffer& framebuffer,
                        const OpeningBoxes& boxes);

}  // namespace cutaway::pipeline

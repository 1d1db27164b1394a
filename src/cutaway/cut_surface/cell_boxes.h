#pragma once
// Draws one point per primary cell through the frustum shaders (cut_surface/frustum.*): the cell's
// box in the cut camera's perspective-divided (u, v, s) space, its back face pushed back by the
// margin and widened by one pixel, plus the walls unless the program was built with
// BACK_FACE_ONLY. Shared by the frustum union and the cone-field seeds, so both see the same boxes.
#include "cutaway/cut_surface/cut_surface_strategy.h"
#include "gl/gl_objects.h"

namespace cutaway::pipeline {

/// The frustum program: frustum.vert/.geom/.frag, with BACK_FACE_ONLY when `back_face_only`.
gl::Program build_cell_box_program(const gl::ShaderLibrary& shaders, bool back_face_only);

/// Sets the program's uniforms from `inputs` and draws every primary cell into `framebuffer`
/// (depth only, GL_GREATER: the framebuffer keeps the farthest hull; the caller clears it to 0).
/// Leaves the depth function at GL_LESS. No-op without primary cells.
void draw_cell_boxes(const gl::Program& program, const CutSurfaceInputs& inputs, const gl::Framebuffer& framebuffer);

}  // namespace cutaway::pipeline

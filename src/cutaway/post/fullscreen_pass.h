#pragma once
// Draws one full-viewport triangle into a framebuffer (every screen-space pass).
#include "gl/gl_objects.h"

namespace cutaway::pipeline {

/// Binds `target`, sets the viewport, disables depth testing and draws with `program`.
void draw_fullscreen(const gl::Program& program, const gl::Framebuffer& target, int width, int height);

}  // namespace cutaway::pipeline

#pragma once
// The colour bar drawn into the image: gradient of the colour map, frame, title with unit, round
// tick values (annotation::layout_colour_bar places them; text from stb_easy_font).
#include "annotation/colour_bar_layout.h"
#include "cutaway/overlay_batch.h"
#include "gl/gl_objects.h"
#include "gl/shader_library.h"

namespace cutaway::pipeline {

using annotation::ColourBarLabel;

class ColourBar {
public:
    explicit ColourBar(const gl::ShaderLibrary& shaders);
    /// Draws into `target` (width x height) at the right edge, as layout_colour_bar places it.
    void draw(const gl::Framebuffer& target, int width, int height, const gl::Texture& colour_map,
              const ColourBarLabel& label);

private:
    OverlayBatch batch_;
};

}  // namespace cutaway::pipeline

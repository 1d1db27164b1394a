#pragma once
// A caption over the final image (an animation frame's date and report step): dark text on a
// light box at the top-left corner (annotation::place_caption), as tall as the colour bar's text.
#include <string>

#include "cutaway/overlay_batch.h"
#include "gl/gl_objects.h"
#include "gl/shader_library.h"

namespace cutaway::pipeline {

/// Rows at the top of a width x height image that `text`'s caption takes, with a margin below it as
/// wide as the one above: the `reserved_top_px` of make_orbit_camera that frames the model below
/// the caption (0 for blank text or an image too small for it). `reserved_right`, `min_text_px`:
/// as draw's.
float caption_reserved_rows(const std::string& text, int width, int height, float reserved_right, float min_text_px);

class FrameCaption {
public:
    explicit FrameCaption(const gl::ShaderLibrary& shaders) : batch_(shaders) {}
    /// Draws `text` onto `target` (width x height); `reserved_right`: the colour bar's columns.
    void draw(const gl::Framebuffer& target, int width, int height, const std::string& text, float reserved_right,
              float min_text_px);

private:
    OverlayBatch batch_;
};

}  // namespace cutaway::pipeline

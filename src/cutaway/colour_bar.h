#pragma once
// The colour bar drawn into the image: gradient of the colour map, frame, title with unit, round
// tick values (annotation::layout_colour_bar places them; text from stb_easy_font).
#include <optional>

#include "annotation/colour_bar_layout.h"
#include "cutaway/overlay_batch.h"
#include "gl/gl_objects.h"
#include "gl/shader_library.h"

namespace cutaway::pipeline {

using annotation::ColourBarLabel;

/// The saturation contrast's factors (FrameSettings::saturation_primary, saturation_secondary).
struct BarSaturation {
    float primaries = 1;
    float secondaries = 1;
};

class ColourBar {
public:
    explicit ColourBar(const gl::ShaderLibrary& shaders);
    /// Draws into `target` (width x height) at the right edge, as layout_colour_bar places it. With
    /// `saturation` the gradient's left half shows the primaries' colours, its right half the
    /// secondaries' (a reader matches either against its own half).
    void draw(const gl::Framebuffer& target, int width, int height, const gl::Texture& colour_map,
              const ColourBarLabel& label, const std::optional<BarSaturation>& saturation = std::nullopt);

private:
    OverlayBatch batch_;
};

}  // namespace cutaway::pipeline

#pragma once
// The transfer function drawn into the image's right margin (annotation::layout_colour_bar places
// it): the fitted window's bottom level at the bottom, its top at the top, round amplitude ticks,
// the title "amplitude". The left half of the gradient shows the colour, the right half the colour
// at the level's opacity relative to the table's largest (so low-opacity ramps stay visible) over
// the background.
#include "annotation/colour_bar_layout.h"
#include "gl/image.h"
#include "volume/volume_scene.h"

namespace cutaway::volume {

/// The bar's label: the title and the amplitudes at the window's ends; its capitals at least
/// `min_text_px` tall (RayCastSettings::text_height_px).
annotation::ColourBarLabel colour_bar_label(const VolumeScene& scene, float min_text_px = 0);

void draw_colour_bar(gl::RgbaImage& image, const VolumeScene& scene, Rgba background, float min_text_px = 0);

}  // namespace cutaway::volume

#pragma once
// What a cast image carries besides the volume: the colour bar and the orientation edges.
#include "gl/image.h"
#include "volume/ray_cast_settings.h"
#include "volume/view_geometry.h"
#include "volume/volume_scene.h"

namespace cutaway::volume {

/// The transfer-function bar (colour_bar.h) and the cube's inline / crossline / time edges
/// (orientation_labels.h), drawn into `image` (settings.width x settings.height).
void draw_annotations(gl::RgbaImage& image, const VolumeScene& scene, const ViewGeometry& view, const RayCastSettings& settings);

}  // namespace cutaway::volume

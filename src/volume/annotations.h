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

/// With settings.colour_bar, the columns the annotations take beside a framed cube: the colour
/// bar's at the right (at most half the width) and the time axis's tick values at the left (at
/// most a quarter), as `cutaway volume` sets them before casting.
void reserve_annotation_room(RayCastSettings& settings, const VolumeScene& scene);

}  // namespace cutaway::volume

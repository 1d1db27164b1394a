#pragma once
// Moving a cut's depth image between the GPU and the CPU. On the GPU (CutTargets::depth, a
// GL_DEPTH_COMPONENT32F texture, rows bottom to top) a pixel stores (s - near) / (far - near) of
// the cut camera, 0 = nothing cut. On the CPU (cone_field::FloatImage, rows top to bottom) it is
// s itself, the depth along the cut camera's view axis (render units), 0 = nothing cut.
#include "cutaway/camera.h"
#include "cone_field/cone_image.h"
#include "gl/gl_objects.h"

namespace cutaway::pipeline {

/// Reads a depth texture of the camera's size into depth units s (0 stays 0).
cone_field::FloatImage read_cut_depth_texture(const gl::Texture& depth, const Camera& camera);

/// Writes `cut` (depth units, the camera's size) into the depth texture. Depths at or in front of
/// the near plane store 0 (nothing lies there to cut); depths beyond the far plane store 1.
/// Throws std::invalid_argument if the sizes differ.
void write_cut_depth_texture(const cone_field::FloatImage& cut, const Camera& camera, const gl::Texture& depth);

/// What a depth survives storing: 0 at or in front of the near plane, at most the far plane.
float storable_cut_depth(float depth, const Camera& camera);

}  // namespace cutaway::pipeline

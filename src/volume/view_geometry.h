#pragma once
// Matrices between voxel space, world and clip space for one frame. Voxel space is the 3D
// texture's: p = (time, crossline, inline) in [0, samples] x [0, crosslines] x [0, inlines], voxel v
// spanning [v, v + 1]. World: x = inline, y = crossline, z = up (time runs down), centred on the cube.
#include <glm/glm.hpp>

#include "volume/quantised_volume.h"
#include "volume/ray_cast_settings.h"

namespace cutaway::volume {

struct ViewGeometry {
    glm::vec3 box;               ///< voxel-space extent (samples, crosslines, inlines)
    glm::mat4 voxel_to_world;
    glm::mat4 voxel_to_clip;     ///< projection * view * voxel_to_world
    glm::mat4 clip_to_voxel;     ///< its inverse
    glm::vec3 eye_voxel;         ///< the eye in voxel space
    double time_scale = 1;       ///< effective (after resolving 0 = automatic)
    double distance = 0;         ///< effective eye distance, world units
    bool mirrored = false;       ///< voxel_to_world flips handedness (front faces wind clockwise)
};

ViewGeometry make_view(const CubeDims& dims, const RayCastSettings& settings);

/// The ray through the centre of pixel (x, y) (x right, y up from the bottom row, GL convention):
/// origin at the eye, unit direction, both in voxel space.
struct VoxelRay {
    glm::vec3 origin;
    glm::vec3 direction;
};
VoxelRay pixel_ray(const ViewGeometry& view, int x, int y, int width, int height);

}  // namespace cutaway::volume

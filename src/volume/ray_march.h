#pragma once
// One ray through the volume on the CPU, step for step what shaders/volume/ray_cast.frag does:
// samples at entry + dir (start + i step), trilinear interpolation of the levels, the table read
// linearly between levels, front-to-back compositing
//   C_out a_out = C_in a_in + C_now a_now (1 - a_in),  a_out = a_in + a_now (1 - a_in),
// and the optional opacity correction, jittered start, early termination and empty-block skipping.
// Skipping advances i by whole steps, so it takes the same sample positions as the naive loop.
#include <cstdint>

#include <glm/glm.hpp>

#include "volume/ray_cast_settings.h"
#include "volume/volume_scene.h"

namespace cutaway::volume {

/// Premultiplied colour and opacity gathered along a ray, and the volume samples it took.
struct RayResult {
    glm::vec3 colour{0};
    float alpha = 0;
    std::uint32_t samples = 0;
};

/// Fraction of a step in [0, 1) for pixel (x, y): PCG hash of the pixel, top 24 bits (exactly
/// representable as a float on CPU and GPU alike).
float jitter_fraction(std::uint32_t x, std::uint32_t y);

/// Level (0..255, continuous) at voxel-space position p, trilinear with clamp-to-edge, as a GL
/// sampler reads a 3D texture at p / box.
float sample_level(const QuantisedVolume& volume, glm::vec3 p);

/// Entry and exit distances of a ray against the box [0, box]; false when it misses.
bool intersect_box(glm::vec3 origin, glm::vec3 direction, glm::vec3 box, float& t_enter, float& t_exit);

/// Marches from `entry` to `exit` (voxel space). `start_fraction` in [0, 1) shifts the first sample.
RayResult march_ray(const VolumeScene& scene, const RayCastSettings& settings, glm::vec3 entry, glm::vec3 exit,
                    float start_fraction);

}  // namespace cutaway::volume

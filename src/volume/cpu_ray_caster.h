#pragma once
// The reference caster: every pixel's ray on the CPU (std::thread workers over rows), the same
// geometry, sampling, transfer function and compositing as the GPU caster.
#include "volume/cast_result.h"
#include "volume/ray_cast_settings.h"
#include "volume/volume_scene.h"

namespace cutaway::volume {

/// `threads` workers (0: std::thread::hardware_concurrency()). The colour bar is drawn when the
/// settings ask for it.
CastResult cast_rays_cpu(const VolumeScene& scene, const RayCastSettings& settings, unsigned threads = 0);

}  // namespace cutaway::volume

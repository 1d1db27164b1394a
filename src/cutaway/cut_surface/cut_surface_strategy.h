#pragma once
// Stage 1 behind one interface: a strategy turns the primary cells into the cut surface (the
// rear hull of what must be removed), written into CutTargets. Stages 2 and 3 read only
// CutTargets, so every strategy's images are comparable.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "cutaway/camera.h"
#include "cutaway/frame_settings.h"
#include "cutaway/frame_targets.h"
#include "cutaway/grid_buffers.h"
#include "gl/shader_library.h"

namespace cutaway::pipeline {

struct CutSurfaceInputs {
    const GridBuffers& grid;
    const Camera& cut_camera;
    float aperture_h_rad = 0;  ///< wall angle from the view ray
    float aperture_v_rad = 0;
    float back_margin = 0;     ///< render units behind each primary's far side
    float rim_depth = 0;       ///< depth (along the view axis) where nothing lies in front: walls stop
    SeedSource seeds = SeedSource::boxes;  ///< for the strategies that start from seeds
};

class CutSurfaceStrategy {
public:
    virtual ~CutSurfaceStrategy() = default;
    /// Writes the cut's depth image into targets.depth, which the caller cleared to 0 ("nothing
    /// cut"): (s - near) / (far - near) of the cut camera, s the depth along its view axis.
    /// The pipeline then rebuilds normals and positions (cut_resolve.h).
    virtual void render(const CutSurfaceInputs& inputs, const CutTargets& targets) = 0;
};

struct CutSurfaceEntry {
    std::string name;
    std::string device;  ///< "gpu" or "cpu"
    std::string why;     ///< why it runs there
    std::function<std::unique_ptr<CutSurfaceStrategy>(const gl::ShaderLibrary&)> make;
};

}  // namespace cutaway::pipeline

#pragma once
// Final image: ambient occlusion, saturation contrast, silhouette and contours over the scene.
#include "cutaway/frame_settings.h"
#include "cutaway/frame_targets.h"
#include "gl/program_cache.h"

namespace cutaway::pipeline {

class Composite {
public:
    explicit Composite(const gl::ShaderLibrary& shaders);
    void apply(const SceneTargets& scene, const PostTargets& post, const FrameSettings& settings, int width, int height);

private:
    gl::ProgramCache programs_;
};

}  // namespace cutaway::pipeline

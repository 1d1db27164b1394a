#pragma once
// Screen-space ambient occlusion from the scene's normals and depths.
#include "cutaway/camera.h"
#include "cutaway/frame_settings.h"
#include "cutaway/frame_targets.h"
#include "gl/program_cache.h"

namespace cutaway::pipeline {

class Ssao {
public:
    explicit Ssao(const gl::ShaderLibrary& shaders);
    /// Writes post.ambient with settings' samples and resolution; `radius` in render units.
    /// `cut_depth`: the resolved cut when it was made from `camera` (else null): where the cut
    /// fill shows the cut, its depth is the surface seen (shaders/post/ssao.comp, CUT_DEPTH).
    void apply(const SceneTargets& scene, const PostTargets& post, const Camera& camera, const FrameSettings& settings,
               float radius, const gl::Texture* cut_depth);

private:
    gl::ProgramCache programs_;
};

}  // namespace cutaway::pipeline

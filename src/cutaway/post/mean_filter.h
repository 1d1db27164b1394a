#pragma once
// Mean filter of the cut surface (k x k, full or sampled kernel), as two 1D passes.
#include "cutaway/camera.h"
#include "cutaway/frame_settings.h"
#include "cutaway/frame_targets.h"
#include "gl/program_cache.h"

namespace cutaway::pipeline {

class MeanFilter {
public:
    explicit MeanFilter(const gl::ShaderLibrary& shaders);
    /// Filters input.depth into output.depth (same size) with an odd kernel `size` >= 3.
    void apply(const CutTargets& input, const CutTargets& output, int size, MeanFilterKernel kernel,
               const Camera& cut_camera);

private:
    const gl::Program& program(int size, MeanFilterKernel kernel, int axis, const Camera& cut_camera);
    gl::ProgramCache programs_;
    gl::Texture rows_;               ///< R32F: the first (row) pass
    gl::Framebuffer rows_framebuffer_;
};

}  // namespace cutaway::pipeline

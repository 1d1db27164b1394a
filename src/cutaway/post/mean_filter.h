#pragma once
// Mean filter of the cut surface (k x k, full or sampled kernel).
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
    gl::ProgramCache programs_;
};

}  // namespace cutaway::pipeline

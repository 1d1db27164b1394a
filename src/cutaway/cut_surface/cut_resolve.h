#pragma once
// Turns a strategy's depth image into the cut-surface targets stage 2 reads: world normal +
// depth (RGBA32F) and the rear-shell clamp flag (R8), one compute pass
// (shaders/cut_surface/resolve.comp).
#include "cutaway/camera.h"
#include "cutaway/frame_targets.h"
#include "gl/float_image_buffer.h"
#include "gl/program_cache.h"

namespace cutaway::pipeline {

class CutResolve {
public:
    explicit CutResolve(const gl::ShaderLibrary& shaders);
    /// Reads targets.depth, writes targets.surface and targets.rear_clamp where a cut is (the
    /// targets must be cleared, CutTargets::clear, since the last apply). `rear_shell` (null: no
    /// clamp): the farthest shell depth (rear_shell_depth.h); the cut is kept `rear_margin`
    /// render units in front of it wherever both exist.
    void apply(const CutTargets& targets, const Camera& cut_camera, const gl::Texture* rear_shell = nullptr,
               float rear_margin = 0);
    /// The same from a depth image already in an image buffer (stored depth, as MeanFilter::filter
    /// returns it) instead of targets.depth: no copy.
    void apply(const gl::FloatImageBuffer& depth, const CutTargets& targets, const Camera& cut_camera,
               const gl::Texture* rear_shell = nullptr, float rear_margin = 0);

private:
    gl::ProgramCache programs_;  ///< resolve.comp, one pixel or 4 (QUADS) per invocation
    gl::FloatImageBuffer depth_, rear_shell_;  ///< the depth images as the pass reads them
};

}  // namespace cutaway::pipeline

#pragma once
// Mean filter of the cut surface (k x k), as two 1D compute passes over image buffers
// (shaders/post/mean_filter.comp). Kernels (SPEC.md stage extras):
//   full: every texel of the k x k window;
//   sampled: every other texel along each axis (a quarter of the loads);
//   distance-scaled: the radius shrinks with distance to the camera, so far cut walls, a few
//     pixels wide, are not smoothed away: r(p) = clamp(round(R * d_ref / d(p)), 1, R), R = k / 2,
//     d(p) the unfiltered cut's depth at p along the cut camera's axis (R where nothing is cut),
//     d_ref = mean_filter_reference_depth (the model centre's depth): beyond it a window of
//     constant size in the model, that of the full kernel at the model's centre; nearer, the full
//     kernel.
//     Separable only approximately: the second pass averages first-pass means taken with each
//     texel's own radius, which is the (2r+1)^2 box mean only where the radius is the same over
//     the window; where it is R over the whole window (the cut nearer than d_ref there) the result
//     is the full kernel's.
#include "cutaway/camera.h"
#include "cutaway/frame_settings.h"
#include "cutaway/frame_targets.h"
#include "cutaway/model_frame.h"
#include "gl/float_image_buffer.h"
#include "gl/program_cache.h"

namespace cutaway::pipeline {

/// d_ref of the distance-scaled kernel: the depth of the model's centre along `cut_camera`'s axis
/// (render units, at least the near plane).
float mean_filter_reference_depth(const ModelFrame& frame, const Camera& cut_camera);

class MeanFilter {
public:
    explicit MeanFilter(const gl::ShaderLibrary& shaders);
    /// Filters input.depth with an odd kernel `size` >= 3 into the returned image buffer (stored
    /// depth, valid until the next call); `reference_depth`: d_ref of the distance-scaled kernel
    /// (unused by the others). CutResolve reads the buffer as it is.
    const gl::FloatImageBuffer& filter(const CutTargets& input, int size, MeanFilterKernel kernel, const Camera& cut_camera,
                                       float reference_depth);
    /// The same, copied into output.depth (same size).
    void apply(const CutTargets& input, const CutTargets& output, int size, MeanFilterKernel kernel,
               const Camera& cut_camera, float reference_depth) {
        filter(input, size, kernel, cut_camera, reference_depth).write_depth(output.depth);
    }

private:
    /// `quads`: the full kernel over 4 pixels per invocation (mean_filter.comp QUADS).
    const gl::Program& program(int size, MeanFilterKernel kernel, int axis, const Camera& cut_camera, float reference_depth,
                               bool quads);
    gl::ProgramCache programs_;
    gl::FloatImageBuffer unfiltered_;  ///< input.depth; the second pass's output where the kernel does not read it then
    gl::FloatImageBuffer rows_;        ///< the first (row) pass
    gl::FloatImageBuffer filtered_;    ///< the second pass's output for the distance-scaled kernel (allocated at its first use)
};

}  // namespace cutaway::pipeline

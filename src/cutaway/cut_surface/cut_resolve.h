#pragma once
// Turns a strategy's depth image into the cut-surface targets stage 2 reads: world normal +
// depth (RGBA32F) and the rear-shell clamp flag (R8), one full-screen pass.
#include "cutaway/camera.h"
#include "cutaway/frame_targets.h"
#include "gl/shader_library.h"

namespace cutaway::pipeline {

class CutResolve {
public:
    explicit CutResolve(const gl::ShaderLibrary& shaders);
    /// Reads targets.depth, writes targets.surface and targets.rear_clamp. `rear_shell` (null: no
    /// clamp): the farthest shell depth (rear_shell_depth.h); the cut is kept `rear_margin`
    /// render units in front of it wherever both exist.
    void apply(const CutTargets& targets, const Camera& cut_camera, const gl::Texture* rear_shell = nullptr,
               float rear_margin = 0);

private:
    gl::Program program_;
};

/// Sets the cut camera uniforms of shaders/cut_surface/cut_output.glsl on `program`.
void set_cut_output_uniforms(const gl::Program& program, const Camera& cut_camera);

}  // namespace cutaway::pipeline

#pragma once
// Stage 3: primary cells with their own edge colour, and the uncut shell's depth for contours.
#include "cutaway/face_drawing.h"
#include "cutaway/frame_settings.h"
#include "cutaway/frame_targets.h"
#include "gl/shader_library.h"

namespace cutaway::pipeline {

class PrimaryPass {
public:
    explicit PrimaryPass(const gl::ShaderLibrary& shaders);
    /// Draws `faces` into the bound scene framebuffer.
    void draw_primaries(const FaceDrawContext& context, const FaceBuffer& faces, const FrameSettings& settings);
    /// --only secondaries: the far walls of the hidden primaries' `faces` that are shell faces
    /// (back-facing), grey, as cut fill, behind anything stage 2 drew at the same depth.
    void draw_hidden_walls(const FaceDrawContext& context, const FaceBuffer& faces);
    /// Draws the nearest outer face's linear depth (GridBuffers::outer_faces) into scene.shell_framebuffer.
    void draw_shell_depth(const FaceDrawContext& context, const SceneTargets& scene);

private:
    gl::Program primaries_;
    gl::Program hidden_walls_;
    gl::Program shell_depth_;
};

}  // namespace cutaway::pipeline

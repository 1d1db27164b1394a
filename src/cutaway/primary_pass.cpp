#include "cutaway/primary_pass.h"

#include "gl/uniforms.h"

namespace cutaway::pipeline {

PrimaryPass::PrimaryPass(const gl::ShaderLibrary& shaders)
    : primaries_(shaders.build({{GL_VERTEX_SHADER, "common/face.vert"}, {GL_FRAGMENT_SHADER, "primary/primary.frag"}},
                               {{"CULL_BACK", ""}})),
      shell_depth_(shaders.build({{GL_VERTEX_SHADER, "common/face_corner.vert"}, {GL_FRAGMENT_SHADER, "primary/shell_depth.frag"}})) {}

void PrimaryPass::draw_primaries(const FaceDrawContext& context, const FaceBuffer& faces, const FrameSettings& settings) {
    prepare_face_program(primaries_, context);
    gl::set_uniform(primaries_, "line_width", settings.line_width_px);
    context.grid.draw_faces(faces);
}

void PrimaryPass::draw_shell_depth(const FaceDrawContext& context, const SceneTargets& scene) {
    scene.shell_framebuffer.bind();
    prepare_face_program(shell_depth_, context);
    context.grid.draw_faces(context.grid.outer_faces(), GL_BACK);  // the nearest, per triangle (common/face_corner.vert)
}

}  // namespace cutaway::pipeline

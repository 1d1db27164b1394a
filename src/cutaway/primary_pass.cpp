#include "cutaway/primary_pass.h"

#include "gl/uniforms.h"

namespace cutaway::pipeline {

PrimaryPass::PrimaryPass(const gl::ShaderLibrary& shaders)
    : primaries_(shaders.build({{GL_VERTEX_SHADER, "common/face.vert"}, {GL_FRAGMENT_SHADER, "primary/primary.frag"}},
                               {{"CULL_BACK", ""}})),
      hidden_walls_(shaders.build({{GL_VERTEX_SHADER, "common/face.vert"}, {GL_FRAGMENT_SHADER, "primary/primary.frag"}},
                                  {{"SHELL_BACKS", ""}, {"HIDDEN_WALLS", ""}})),
      shell_depth_(shaders.build({{GL_VERTEX_SHADER, "common/face_corner.vert"}, {GL_FRAGMENT_SHADER, "primary/shell_depth.frag"}})) {}

void PrimaryPass::draw_primaries(const FaceDrawContext& context, const FaceBuffer& faces, const FrameSettings& settings) {
    prepare_face_program(primaries_, context);
    gl::set_uniform(primaries_, "line_width", settings.line_width_px);
    context.grid.draw_faces(faces);
}

void PrimaryPass::draw_hidden_walls(const FaceDrawContext& context, const FaceBuffer& faces) {
    prepare_face_program(hidden_walls_, context);
    // A few depth units back: where a shell face is drawn by stage 2 as well, stage 2's wins.
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 4.0f);
    context.grid.draw_faces(faces);
    glDisable(GL_POLYGON_OFFSET_FILL);
}

void PrimaryPass::draw_shell_depth(const FaceDrawContext& context, const SceneTargets& scene) {
    scene.shell_framebuffer.bind();
    prepare_face_program(shell_depth_, context);
    context.grid.draw_faces(context.grid.outer_faces(), GL_BACK);  // the nearest, per triangle (common/face_corner.vert)
}

}  // namespace cutaway::pipeline

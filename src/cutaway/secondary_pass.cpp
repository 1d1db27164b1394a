#include "cutaway/secondary_pass.h"

#include "gl/uniforms.h"

namespace cutaway::pipeline {

SecondaryPass::SecondaryPass(const gl::ShaderLibrary& shaders)
    : programs_(shaders, {{GL_VERTEX_SHADER, "common/face.vert"}, {GL_FRAGMENT_SHADER, "secondary/secondary.frag"}}) {}

void SecondaryPass::draw(const FaceDrawContext& context, const FaceBuffer& faces, const FrameSettings& settings,
                         const CutTargets& cut, const Camera& cut_camera) {
    gl::ShaderDefines defines{{"CULL_FRONT_INTERIOR", ""},
                              {settings.border == BorderMode::raycast ? "BORDER_RAYCAST" : "BORDER_THRESHOLD", ""}};
    if (settings.hide_internal_lines) defines.emplace_back("HIDE_INTERNAL_LINES", "");
    const gl::Program& p = programs_.get(defines);
    prepare_face_program(p, context);
    gl::set_uniform(p, "cut_surface", 1);
    cut.surface.bind(1);
    gl::set_uniform(p, "cut_view", cut_camera.view);
    gl::set_uniform(p, "cut_projection", cut_camera.projection);
    gl::set_uniform(p, "cut_size", glm::vec2(float(cut_camera.width), float(cut_camera.height)));
    gl::set_uniform(p, "inverse_view_projection", glm::inverse(context.camera.view_projection()));
    gl::set_uniform(p, "focal_px", context.camera.focal_px());
    gl::set_uniform(p, "line_width", settings.line_width_px);
    gl::set_uniform(p, "border_width", settings.border_width_px);
    gl::set_uniform(p, "edge_colour", glm::vec3(0.12f, 0.12f, 0.12f));
    gl::set_uniform(p, "border_colour", glm::vec3(0.0f, 0.0f, 0.0f));
    gl::set_uniform(p, "shell_cut_colour", glm::vec3(0.85f, 0.1f, 0.1f));
    GridBuffers::draw_faces(faces);
}

}  // namespace cutaway::pipeline

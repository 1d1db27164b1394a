#include "cutaway/secondary_pass.h"

#include "cutaway/post/fullscreen_pass.h"
#include "gl/uniforms.h"

namespace cutaway::pipeline {

SecondaryPass::SecondaryPass(const gl::ShaderLibrary& shaders)
    : programs_(shaders, {{GL_VERTEX_SHADER, "common/face.vert"}, {GL_FRAGMENT_SHADER, "secondary/secondary.frag"}}),
      plain_(shaders, {{GL_VERTEX_SHADER, "common/face.vert"}, {GL_FRAGMENT_SHADER, "secondary/plain.frag"}}),
      borders_(shaders.build({{GL_VERTEX_SHADER, "post/fullscreen.vert"},
                              {GL_FRAGMENT_SHADER, "secondary/raycast_borders.frag"}})) {}

namespace {
/// The uniforms of shaders/common/cut_lookup.glsl; `camera`: the model camera.
void set_cut_lookup(const gl::Program& p, const CutClip& clip, const Camera& camera) {
    const Camera& cut_camera = clip.cut_camera;
    gl::set_uniform(p, "cut_surface", 1);
    clip.cut.surface.bind(1);
    gl::set_uniform(p, "cut_position", 5);
    clip.cut.position.bind(5);
    gl::set_uniform(p, "cut_view", cut_camera.view);
    gl::set_uniform(p, "cut_projection", cut_camera.projection);
    gl::set_uniform(p, "cut_view_projection", cut_camera.view_projection());
    gl::set_uniform(p, "cut_size", glm::vec2(float(cut_camera.width), float(cut_camera.height)));
    // Its own unit even when unused: two sampler types may not share one (the colour map's is 0).
    gl::set_uniform(p, "view_rear_shell", 6);
    gl::set_uniform(p, "keep_view_rear_shell", clip.view_rear_shell != nullptr);
    if (!clip.view_rear_shell) return;
    clip.view_rear_shell->bind(6);
    gl::set_uniform(p, "view_rear_view", camera.view);
    gl::set_uniform(p, "view_rear_range", glm::vec2(camera.near_plane, camera.far_plane));
    gl::set_uniform(p, "view_rear_margin", clip.rear_margin);
}
const glm::vec3 shell_cut_colour(0.85f, 0.1f, 0.1f);
}  // namespace

void SecondaryPass::apply_raycast_borders(const Camera& camera, const SceneTargets& scene, const FrameSettings& settings,
                                          const CutClip& clip) {
    const gl::Program& p = borders_;
    set_cut_lookup(p, clip, camera);
    gl::set_uniform(p, "inverse_view_projection", glm::inverse(camera.view_projection()));
    gl::set_uniform(p, "inverse_view", glm::inverse(camera.view));
    gl::set_uniform(p, "projection_scale", glm::vec2(camera.projection[0][0], camera.projection[1][1]));
    gl::set_uniform(p, "viewport_size", glm::vec2(float(camera.width), float(camera.height)));
    gl::set_uniform(p, "border_width", settings.border_width_px);
    gl::set_uniform(p, "shell_cut_colour", shell_cut_colour);
    gl::set_uniform(p, "hide_internal_lines", settings.hide_internal_lines);
    gl::set_uniform(p, "face_plane", 2);
    gl::set_uniform(p, "normal_depth", 3);
    scene.face_plane.bind(2);
    scene.normal_depth.bind(3);
    gl::set_uniform(p, "scene_colour", 0);
    gl::set_uniform(p, "scene_id", 1);
    glBindImageTexture(0, scene.colour.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA8);
    glBindImageTexture(1, scene.id.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RG32UI);
    glNamedFramebufferParameteri(no_attachments_.id(), GL_FRAMEBUFFER_DEFAULT_WIDTH, camera.width);
    glNamedFramebufferParameteri(no_attachments_.id(), GL_FRAMEBUFFER_DEFAULT_HEIGHT, camera.height);
    draw_fullscreen(p, no_attachments_, camera.width, camera.height);
    glMemoryBarrier(GL_ALL_BARRIER_BITS);
}

void SecondaryPass::draw(const FaceDrawContext& context, const std::function<void()>& submit, const FrameSettings& settings,
                         const CutClip& clip) {
    gl::ShaderDefines defines{{"CULL_FRONT_INTERIOR", ""},
                              {settings.border == BorderMode::raycast ? "BORDER_RAYCAST" : "BORDER_THRESHOLD", ""}};
    if (settings.hide_internal_lines) defines.emplace_back("HIDE_INTERNAL_LINES", "");
    const gl::Program& p = programs_.get(defines);
    prepare_face_program(p, context);
    set_cut_lookup(p, clip, context.camera);
    gl::set_uniform(p, "focal_px", context.camera.focal_px());
    gl::set_uniform(p, "line_width", settings.line_width_px);
    gl::set_uniform(p, "border_width", settings.border_width_px);
    gl::set_uniform(p, "shell_cut_colour", shell_cut_colour);
    submit();
}

void SecondaryPass::draw_plain(const FaceDrawContext& context, const std::function<void()>& submit,
                               const FrameSettings& settings, DrawMode draw) {
    const gl::ShaderDefines defines = draw == DrawMode::visible
        ? gl::ShaderDefines{{"PLAIN_FRAME", ""}, {"STORED_CORNERS", ""}, {"CULL_HIDDEN_BACK", ""}}
        : gl::ShaderDefines{{"PLAIN_FRAME", ""}, {"CULL_FRONT_INTERIOR", ""}};
    const gl::Program& p = plain_.get(defines);
    prepare_face_program(p, context);
    gl::set_uniform(p, "line_width", settings.line_width_px);
    submit();
}

}  // namespace cutaway::pipeline

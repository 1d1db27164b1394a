#include "cutaway/post/composite.h"

#include "cutaway/post/fullscreen_pass.h"
#include "gl/uniforms.h"

namespace cutaway::pipeline {

namespace {
/// Cyan: apart from the red shell-cut lines and from the viridis map (the domain experts asked
/// for a colour and line style of its own).
const glm::vec3 silhouette_colour(0.0f, 0.8f, 1.0f);
}  // namespace

Composite::Composite(const gl::ShaderLibrary& shaders)
    : programs_(shaders, {{GL_VERTEX_SHADER, "post/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "post/composite.frag"}}) {}

void Composite::apply(const SceneTargets& scene, const PostTargets& post, const FrameSettings& settings, int width,
                      int height) {
    gl::ShaderDefines defines;
    if (settings.ssao) defines.emplace_back("SSAO", "");
    if (settings.saturation) defines.emplace_back("SATURATION", "");
    if (settings.silhouette) defines.emplace_back("SILHOUETTE", "");
    if (settings.contours) defines.emplace_back("CONTOURS", "");
    const gl::Program& p = programs_.get(defines);
    gl::set_uniform(p, "scene_colour", 0);
    gl::set_uniform(p, "ambient", 1);
    gl::set_uniform(p, "scene_id", 2);
    gl::set_uniform(p, "shell_depth", 3);
    scene.colour.bind(0);
    post.ambient.bind(1);
    scene.id.bind(2);
    scene.shell_depth.bind(3);
    gl::set_uniform(p, "viewport_size", glm::vec2(float(width), float(height)));
    gl::set_uniform(p, "saturation_primary", settings.saturation_primary);
    gl::set_uniform(p, "saturation_secondary", settings.saturation_secondary);
    gl::set_uniform(p, "silhouette_width", settings.silhouette_width_px);
    gl::set_uniform(p, "silhouette_colour", silhouette_colour);
    gl::set_uniform(p, "contour_colour", glm::vec3(0.05f, 0.05f, 0.05f));
    gl::set_uniform(p, "contour_jump", 0.02f);
    gl::set_uniform(p, "background", glm::vec3(1.0f, 1.0f, 1.0f));
    draw_fullscreen(p, post.final_framebuffer, width, height);
}

}  // namespace cutaway::pipeline

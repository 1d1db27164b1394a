#include "cutaway/post/composite.h"

#include "common/shared_constants.h"
#include "gl/compute_dispatch.h"
#include "gl/uniforms.h"

namespace cutaway::pipeline {

namespace {
/// Cyan: apart from the red shell-cut lines and from the viridis map (the domain experts asked
/// for a colour and line style of its own).
const glm::vec3 silhouette_colour(0.0f, 0.8f, 1.0f);
}  // namespace

Composite::Composite(const gl::ShaderLibrary& shaders)
    : programs_(shaders, {{GL_COMPUTE_SHADER, "post/composite.comp"}}) {}

void Composite::apply(const SceneTargets& scene, const PostTargets& post, const FrameSettings& settings, int width,
                      int height) {
    gl::ShaderDefines defines;
    if (settings.ssao) defines.emplace_back("SSAO", "");
    if (settings.ssao && settings.ssao_half_resolution) defines.emplace_back("HALF_AMBIENT", "");
    if (settings.saturation) defines.emplace_back("SATURATION", "");
    if (settings.silhouette) defines.emplace_back("SILHOUETTE", "");
    if (settings.contours) defines.emplace_back("CONTOURS", "");
    const gl::Program& p = programs_.get(defines);
    glBindImageTexture(shared::img_scene_colour, scene.colour.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA8);
    glBindImageTexture(shared::img_post_ambient, post.ambient.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RG32F);
    glBindImageTexture(shared::img_scene_id, scene.id.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RG32UI);
    glBindImageTexture(shared::img_post_shell_depth, scene.shell_depth.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32F);
    glBindImageTexture(shared::img_post_final_colour, post.final_colour.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
    glBindImageTexture(shared::img_scene_normal_depth, scene.normal_depth.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RG32UI);
    gl::set_uniform(p, "viewport_size", glm::vec2(float(width), float(height)));
    gl::set_uniform(p, "saturation_primary", settings.saturation_primary);
    gl::set_uniform(p, "saturation_secondary", settings.saturation_secondary);
    gl::set_uniform(p, "silhouette_width", settings.silhouette_width_px);
    gl::set_uniform(p, "silhouette_colour", silhouette_colour);
    gl::set_uniform(p, "contour_colour", glm::vec3(0.05f, 0.05f, 0.05f));
    gl::set_uniform(p, "contour_jump", 0.02f);
    gl::set_uniform(p, "background", glm::vec3(1.0f, 1.0f, 1.0f));
    gl::wait_for_draws_before_image_loads();
    p.use();
    gl::dispatch_over(p, width, height);
    // Then drawn over (colour bar), read back or blitted.
    glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                    GL_PIXEL_BUFFER_BARRIER_BIT);
}

}  // namespace cutaway::pipeline

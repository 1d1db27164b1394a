#include "cutaway/post/ssao.h"

#include "common/shared_constants.h"
#include "gl/compute_dispatch.h"
#include "gl/uniforms.h"

namespace cutaway::pipeline {

Ssao::Ssao(const gl::ShaderLibrary& shaders)
    : programs_(shaders, {{GL_COMPUTE_SHADER, "post/ssao.comp"}}) {}

void Ssao::apply(const SceneTargets& scene, const PostTargets& post, const Camera& camera,
                 const FrameSettings& settings, float radius, const gl::Texture* cut_depth) {
    gl::ShaderDefines defines{{"SAMPLES", std::to_string(settings.ssao_samples)}};
    if (settings.ssao_half_resolution) defines.emplace_back("HALF_RESOLUTION", "");
    if (cut_depth) {
        defines.emplace_back("CUT_DEPTH", "");
        glBindImageTexture(shared::img_scene_id, scene.id.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RG32UI);
        glBindImageTexture(shared::img_post_cut_depth, cut_depth->id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32F);
    }
    const gl::Program& p = programs_.get(defines);
    gl::set_uniform(p, "projection_scale", glm::vec2(camera.projection[0][0], camera.projection[1][1]));
    gl::set_uniform(p, "viewport_size", glm::vec2(float(camera.width), float(camera.height)));
    gl::set_uniform(p, "radius", radius);
    gl::set_uniform(p, "strength", settings.ssao_strength);
    gl::set_uniform(p, "min_factor", settings.ssao_min_factor);
    glBindImageTexture(shared::img_scene_normal_depth, scene.normal_depth.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RG32UI);
    glBindImageTexture(shared::img_post_ambient, post.ambient.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RG32F);
    gl::wait_for_draws_before_image_loads();
    p.use();
    const int shrink = settings.ssao_half_resolution ? 2 : 1;
    gl::dispatch_over(p, (camera.width + shrink - 1) / shrink, (camera.height + shrink - 1) / shrink);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
}

}  // namespace cutaway::pipeline

#include "cutaway/post/ssao.h"

#include "cutaway/post/fullscreen_pass.h"
#include "gl/uniforms.h"

namespace cutaway::pipeline {

Ssao::Ssao(const gl::ShaderLibrary& shaders)
    : programs_(shaders, {{GL_VERTEX_SHADER, "post/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "post/ssao.frag"}}) {}

void Ssao::apply(const SceneTargets& scene, const PostTargets& post, const Camera& camera, int samples, float radius) {
    const gl::Program& p = programs_.get({{"SAMPLES", std::to_string(samples)}});
    gl::set_uniform(p, "normal_depth", 0);
    scene.normal_depth.bind(0);
    gl::set_uniform(p, "projection_scale", glm::vec2(camera.projection[0][0], camera.projection[1][1]));
    gl::set_uniform(p, "viewport_size", glm::vec2(float(camera.width), float(camera.height)));
    gl::set_uniform(p, "radius", radius);
    gl::set_uniform(p, "strength", 1.6f);
    draw_fullscreen(p, post.ambient_framebuffer, camera.width, camera.height);
}

}  // namespace cutaway::pipeline

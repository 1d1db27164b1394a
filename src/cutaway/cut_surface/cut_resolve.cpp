#include "cutaway/cut_surface/cut_resolve.h"

#include "cutaway/post/fullscreen_pass.h"
#include "gl/uniforms.h"

namespace cutaway::pipeline {

void set_cut_output_uniforms(const gl::Program& p, const Camera& camera) {
    gl::set_uniform(p, "inverse_cut_view", glm::inverse(camera.view));
    gl::set_uniform(p, "projection_scale", glm::vec2(camera.projection[0][0], camera.projection[1][1]));
    gl::set_uniform(p, "cut_size", glm::vec2(float(camera.width), float(camera.height)));
    gl::set_uniform(p, "cut_near", camera.near_plane);
    gl::set_uniform(p, "cut_far", camera.far_plane);
}

CutResolve::CutResolve(const gl::ShaderLibrary& shaders)
    : program_(shaders.build({{GL_VERTEX_SHADER, "post/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "cut_surface/resolve.frag"}})) {}

void CutResolve::apply(const CutTargets& targets, const Camera& cut_camera, const gl::Texture* rear_shell,
                       float rear_margin) {
    set_cut_output_uniforms(program_, cut_camera);
    gl::set_uniform(program_, "cut_depth", 0);
    gl::set_uniform(program_, "rear_shell_depth", 1);
    gl::set_uniform(program_, "clamp_to_rear_shell", rear_shell != nullptr);
    gl::set_uniform(program_, "rear_margin", rear_margin);
    targets.depth.bind(0);
    if (rear_shell) rear_shell->bind(1);
    // The depth texture is read while the framebuffer that owns it is bound: no depth writes or
    // tests happen in this pass, so there is no feedback loop.
    glDepthMask(GL_FALSE);
    draw_fullscreen(program_, targets.framebuffer, cut_camera.width, cut_camera.height);
    glDepthMask(GL_TRUE);
}

}  // namespace cutaway::pipeline

#include "cutaway/cut_surface/cut_resolve.h"

#include "gl/compute_dispatch.h"
#include "gl/uniforms.h"

namespace cutaway::pipeline {

CutResolve::CutResolve(const gl::ShaderLibrary& shaders) : program_(shaders.build({{GL_COMPUTE_SHADER, "cut_surface/resolve.comp"}})) {}

void CutResolve::apply(const CutTargets& targets, const Camera& cut_camera, const gl::Texture* rear_shell,
                       float rear_margin) {
    depth_.resize(cut_camera.width, cut_camera.height);
    depth_.read_depth(targets.depth);
    apply(depth_, targets, cut_camera, rear_shell, rear_margin);
}

void CutResolve::apply(const gl::FloatImageBuffer& depth, const CutTargets& targets, const Camera& cut_camera,
                       const gl::Texture* rear_shell, float rear_margin) {
    const int width = cut_camera.width, height = cut_camera.height;
    const glm::mat4 inverse_view = glm::inverse(cut_camera.view);
    gl::set_uniform(program_, "inverse_cut_view", inverse_view);
    gl::set_uniform(program_, "cut_camera_position", glm::vec3(inverse_view[3]));
    gl::set_uniform(program_, "projection_scale", glm::vec2(cut_camera.projection[0][0], cut_camera.projection[1][1]));
    gl::set_uniform(program_, "cut_size", glm::ivec2(width, height));
    gl::set_uniform(program_, "cut_near", cut_camera.near_plane);
    gl::set_uniform(program_, "cut_far", cut_camera.far_plane);
    gl::set_uniform(program_, "clamp_to_rear_shell", rear_shell != nullptr);
    gl::set_uniform(program_, "rear_margin", rear_margin);
    depth.bind_image(0, GL_READ_ONLY);
    if (rear_shell) {
        rear_shell_.resize(width, height);
        rear_shell_.read_depth(*rear_shell);
        rear_shell_.bind_image(1, GL_READ_ONLY);
    } else {
        depth.bind_image(1, GL_READ_ONLY);  // not read (clamp_to_rear_shell false), but bound
    }
    glBindImageTexture(2, targets.surface.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindImageTexture(3, targets.rear_clamp.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R8);
    program_.use();
    glDispatchCompute(gl::group_count(width, 64), gl::group_count(height, 4), 1);  // resolve.comp's 64 x 4
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
}

}  // namespace cutaway::pipeline

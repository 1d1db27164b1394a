#include "cutaway/cut_surface/cut_resolve.h"

#include "gl/compute_dispatch.h"
#include "gl/uniforms.h"

namespace cutaway::pipeline {

CutResolve::CutResolve(const gl::ShaderLibrary& shaders) : programs_(shaders, {{GL_COMPUTE_SHADER, "cut_surface/resolve.comp"}}) {}

void CutResolve::apply(const CutTargets& targets, const Camera& cut_camera, const gl::Texture* rear_shell,
                       float rear_margin) {
    depth_.resize(cut_camera.width, cut_camera.height);
    depth_.read_depth(targets.depth);
    apply(depth_, targets, cut_camera, rear_shell, rear_margin);
}

void CutResolve::apply(const gl::FloatImageBuffer& depth, const CutTargets& targets, const Camera& cut_camera,
                       const gl::Texture* rear_shell, float rear_margin) {
    const int width = cut_camera.width, height = cut_camera.height;
    // 4 pixels per invocation where a row is whole 4-pixel texels (resolve.comp QUADS).
    const bool quads = depth.has_quad_view();
    const gl::Program& program = programs_.get(quads ? gl::ShaderDefines{{"QUADS", ""}} : gl::ShaderDefines{});
    gl::set_uniform(program, "cut_size", glm::ivec2(width, height));
    gl::set_uniform(program, "cut_near", cut_camera.near_plane);
    gl::set_uniform(program, "cut_far", cut_camera.far_plane);
    gl::set_uniform(program, "clamp_to_rear_shell", rear_shell != nullptr);
    gl::set_uniform(program, "rear_margin", rear_margin);
    if (rear_shell) {
        rear_shell_.resize(width, height);
        rear_shell_.read_depth(*rear_shell);
    }
    const gl::FloatImageBuffer& rear = rear_shell ? rear_shell_ : depth;  // not read without a rear shell, but bound
    if (quads) {
        depth.bind_quad_image(4, GL_READ_ONLY);
        rear.bind_quad_image(5, GL_READ_ONLY);
    } else {
        depth.bind_image(0, GL_READ_ONLY);
        rear.bind_image(1, GL_READ_ONLY);
    }
    glBindImageTexture(2, targets.surface.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    glBindImageTexture(3, targets.rear_clamp.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R8);
    program.use();
    gl::dispatch_over(program, quads ? width / 4 : width, height);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
}

}  // namespace cutaway::pipeline

#include "cutaway/cut_surface/gpu_cone_transform.h"

#include "gl/uniforms.h"

namespace cutaway::pipeline {

namespace {
gl::ShaderDefines with(gl::ShaderDefines defines, std::initializer_list<gl::ShaderDefine> more) {
    defines.insert(defines.end(), more);
    return defines;
}
}  // namespace

SeedInitPrograms::SeedInitPrograms(const gl::ShaderLibrary& shaders, const char* compute_shader, const gl::ShaderDefines& defines)
    : plain_(shaders.build({{GL_COMPUTE_SHADER, compute_shader}}, with(defines, {{"INIT", ""}}))),
      widened_(shaders.build({{GL_COMPUTE_SHADER, compute_shader}}, with(defines, {{"INIT", ""}, {"WIDEN_SEEDS", ""}}))) {}

const gl::Program& SeedInitPrograms::prepare(const GpuConeInput& input) const {
    const gl::Program& program = input.widen_seeds ? widened_ : plain_;
    gl::set_uniform(program, "seeds", 0);
    input.seeds.bind(0);
    return program;
}

void write_cut_depth(const gl::Program& program, const CutTargets& targets) {
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    targets.framebuffer.bind();
    glViewport(0, 0, targets.depth.width(), targets.depth.height());
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_TRUE);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);  // the resolve pass (cut_resolve.h) writes those
    program.use();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthFunc(GL_LESS);
}

}  // namespace cutaway::pipeline

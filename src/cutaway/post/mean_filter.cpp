#include "cutaway/post/mean_filter.h"

#include "gl/uniforms.h"

namespace cutaway::pipeline {

MeanFilter::MeanFilter(const gl::ShaderLibrary& shaders)
    : programs_(shaders, {{GL_VERTEX_SHADER, "post/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "post/mean_filter.frag"}}) {}

void MeanFilter::apply(const CutTargets& input, const CutTargets& output, int size, MeanFilterKernel kernel,
                       const Camera& cut_camera) {
    gl::ShaderDefines defines{{"KERNEL", std::to_string(size)}};
    if (kernel == MeanFilterKernel::sampled) defines.emplace_back("SAMPLED", "");
    const gl::Program& p = programs_.get(defines);
    gl::set_uniform(p, "cut_depth", 0);
    input.depth.bind(0);
    gl::set_uniform(p, "cut_size", glm::vec2(float(cut_camera.width), float(cut_camera.height)));
    // Writes gl_FragDepth into output.depth: depth testing on with GL_ALWAYS, colour untouched.
    output.framebuffer.bind();
    glViewport(0, 0, cut_camera.width, cut_camera.height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_TRUE);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    p.use();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthFunc(GL_LESS);
}

}  // namespace cutaway::pipeline

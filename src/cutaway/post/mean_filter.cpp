#include "cutaway/post/mean_filter.h"

#include "cutaway/post/fullscreen_pass.h"
#include "gl/uniforms.h"

namespace cutaway::pipeline {

MeanFilter::MeanFilter(const gl::ShaderLibrary& shaders)
    : programs_(shaders, {{GL_VERTEX_SHADER, "post/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "post/mean_filter.frag"}}) {}

void MeanFilter::apply(const CutTargets& input, const CutTargets& output, int size, MeanFilterKernel kernel,
                       const Camera& cut_camera) {
    gl::ShaderDefines defines{{"KERNEL", std::to_string(size)}};
    if (kernel == MeanFilterKernel::sampled) defines.emplace_back("SAMPLED", "");
    const gl::Program& p = programs_.get(defines);
    gl::set_uniform(p, "cut_input", 0);
    input.surface.bind(0);
    gl::set_uniform(p, "inverse_cut_view", glm::inverse(cut_camera.view));
    gl::set_uniform(p, "projection_scale", glm::vec2(cut_camera.projection[0][0], cut_camera.projection[1][1]));
    gl::set_uniform(p, "cut_size", glm::vec2(float(cut_camera.width), float(cut_camera.height)));
    draw_fullscreen(p, output.framebuffer, cut_camera.width, cut_camera.height);
}

}  // namespace cutaway::pipeline

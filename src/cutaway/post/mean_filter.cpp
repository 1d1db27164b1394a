#include "cutaway/post/mean_filter.h"

#include <algorithm>
#include <array>

#include "cutaway/post/fullscreen_pass.h"
#include "gl/uniforms.h"

namespace cutaway::pipeline {

MeanFilter::MeanFilter(const gl::ShaderLibrary& shaders)
    : programs_(shaders, {{GL_VERTEX_SHADER, "post/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "post/mean_filter.frag"}}) {}

float mean_filter_reference_depth(const ModelFrame& frame, const Camera& cut_camera) {
    const glm::vec3 centre = 0.5f * (frame.render_min + frame.render_max);
    return std::max(-(cut_camera.view * glm::vec4(centre, 1.0f)).z, cut_camera.near_plane);
}

const gl::Program& MeanFilter::program(int size, MeanFilterKernel kernel, int axis, const Camera& cut_camera,
                                       float reference_depth) {
    gl::ShaderDefines defines{{"KERNEL", std::to_string(size)}, {"AXIS", std::to_string(axis)}};
    if (kernel == MeanFilterKernel::sampled) defines.emplace_back("SAMPLED", "");
    if (kernel == MeanFilterKernel::distance_scaled) defines.emplace_back("DISTANCE_SCALED", "");
    const gl::Program& p = programs_.get(defines);
    gl::set_uniform(p, "cut_depth", 0);
    gl::set_uniform(p, "cut_size", glm::vec2(float(cut_camera.width), float(cut_camera.height)));
    gl::set_uniform(p, "unfiltered_depth", 1);
    gl::set_uniform(p, "reference_depth", reference_depth);
    gl::set_uniform(p, "cut_range", glm::vec2(cut_camera.near_plane, cut_camera.far_plane));
    return p;
}

void MeanFilter::apply(const CutTargets& input, const CutTargets& output, int size, MeanFilterKernel kernel,
                       const Camera& cut_camera, float reference_depth) {
    if (rows_.width() != cut_camera.width || rows_.height() != cut_camera.height) {
        rows_ = gl::Texture(GL_TEXTURE_2D, GL_R32F, cut_camera.width, cut_camera.height);
        rows_framebuffer_ = gl::Framebuffer();
        rows_framebuffer_.attach(GL_COLOR_ATTACHMENT0, rows_);
        const std::array<GLenum, 1> buffers{GL_COLOR_ATTACHMENT0};
        rows_framebuffer_.finish(buffers, "mean filter rows");
    }
    // Pass 1: along x into rows_.
    input.depth.bind(0);
    input.depth.bind(1);  // the distance-scaled kernel's radius, in both passes
    draw_fullscreen(program(size, kernel, 0, cut_camera, reference_depth), rows_framebuffer_, cut_camera.width,
                    cut_camera.height);
    // Pass 2: along y, written as gl_FragDepth into output.depth (depth test on, GL_ALWAYS).
    const gl::Program& columns = program(size, kernel, 1, cut_camera, reference_depth);
    rows_.bind(0);
    output.framebuffer.bind();
    glViewport(0, 0, cut_camera.width, cut_camera.height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_TRUE);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    columns.use();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthFunc(GL_LESS);
}

}  // namespace cutaway::pipeline

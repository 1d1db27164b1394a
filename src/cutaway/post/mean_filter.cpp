#include "cutaway/post/mean_filter.h"

#include <algorithm>

#include "gl/compute_dispatch.h"
#include "gl/uniforms.h"

namespace cutaway::pipeline {

// Compute passes over image buffers instead of full-screen fragment passes reading the depth
// texture: on llvmpipe the two passes and the compute resolve after them cost a fraction of the
// fragment passes' time (bench_cutaway's mean_filter stage measures it). The frame is byte-identical
// (the same taps, sums in the same order; MeanFilter.EqualsTheBoxMeanOnRandomDepthImages checks
// the mean itself). The frame's resolve reads the filter's output buffer as it is (filter()),
// without copying it into a depth texture and back.
MeanFilter::MeanFilter(const gl::ShaderLibrary& shaders) : programs_(shaders, {{GL_COMPUTE_SHADER, "post/mean_filter.comp"}}) {}

float mean_filter_reference_depth(const ModelFrame& frame, const Camera& cut_camera) {
    const glm::vec3 centre = 0.5f * (frame.render_min + frame.render_max);
    return std::max(-(cut_camera.view * glm::vec4(centre, 1.0f)).z, cut_camera.near_plane);
}

const gl::Program& MeanFilter::program(int size, MeanFilterKernel kernel, int axis, const Camera& cut_camera,
                                       float reference_depth, bool quads) {
    gl::ShaderDefines defines{{"KERNEL", std::to_string(size)}, {"AXIS", std::to_string(axis)}};
    if (quads) defines.emplace_back("QUADS", "");
    if (kernel == MeanFilterKernel::sampled) defines.emplace_back("SAMPLED", "");
    if (kernel == MeanFilterKernel::distance_scaled) defines.emplace_back("DISTANCE_SCALED", "");
    const gl::Program& p = programs_.get(defines);
    gl::set_uniform(p, "size", glm::ivec2(cut_camera.width, cut_camera.height));
    if (kernel == MeanFilterKernel::distance_scaled) {
        gl::set_uniform(p, "reference_depth", reference_depth);
        gl::set_uniform(p, "cut_range", glm::vec2(cut_camera.near_plane, cut_camera.far_plane));
    }
    return p;
}

const gl::FloatImageBuffer& MeanFilter::filter(const CutTargets& input, int size, MeanFilterKernel kernel,
                                               const Camera& cut_camera, float reference_depth) {
    const int width = cut_camera.width, height = cut_camera.height;
    const bool reads_unfiltered = kernel == MeanFilterKernel::distance_scaled;  // in both passes (radius_at)
    unfiltered_.resize(width, height);
    rows_.resize(width, height);
    if (reads_unfiltered) filtered_.resize(width, height);
    const gl::FloatImageBuffer& columns_out = reads_unfiltered ? filtered_ : unfiltered_;
    // The full kernel takes 4 pixels per invocation where a row is whole 4-pixel texels.
    const bool quads = kernel == MeanFilterKernel::full && unfiltered_.has_quad_view();
    const int invocations_x = quads ? width / 4 : width;
    const auto bind = [quads](const gl::FloatImageBuffer& image, GLuint unit, GLenum access) {
        if (quads) image.bind_quad_image(unit, access);
        else image.bind_image(unit, access);
    };

    unfiltered_.read_depth(input.depth);
    unfiltered_.bind_image(2, GL_READ_ONLY);  // the distance-scaled kernel's radius, in both passes
    const auto pass = [&](int axis, const gl::FloatImageBuffer& from, const gl::FloatImageBuffer& to) {
        bind(from, 0, GL_READ_ONLY);
        bind(to, 1, GL_WRITE_ONLY);
        const gl::Program& p = program(size, kernel, axis, cut_camera, reference_depth, quads);
        p.use();
        gl::dispatch_over(p, invocations_x, height);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    };
    pass(0, unfiltered_, rows_);     // along x
    pass(1, rows_, columns_out);     // along y
    return columns_out;
}

}  // namespace cutaway::pipeline

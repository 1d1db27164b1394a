// Jump flooding on the GPU: one compute pass per step (jfa_steps), ping-ponging two RG32UI
// images of owners (seed position and stored depth per pixel, shaders/cut_surface/jump_flood.comp),
// then one fragment pass writing each owner cone's height as the cut depth. On llvmpipe, image
// loads with "0 = no owner" (out-of-image loads read 0: no bounds tests) and selects instead of
// branches made a pass about 2.5x faster than texelFetch with branches (same run, loaded machine).
// Work groups of 64 x 4 passed JFA^2's 22 passes about 11% faster than 8 x 8 (16 x 16: slower, 32 x 8:
// the same); shader storage buffers instead of the images (a select for outside taps) were slower
// (zaphirus, 1920x1080, two alternating runs each, LP_NUM_THREADS=2, issue 16). The same pass as
// a fragment shader (full-screen triangle into an RG32UI attachment, texelFetch with clamped taps)
// took 300 ms for sapphire's 11 passes against the compute passes' 135 ms; 128 x 8, 32 x 32 and
// 8 x 8 groups were within noise of 64 x 4 (1920x1080, LP_NUM_THREADS=2).
//
// Against the CPU reference (cone_field/jump_flooding.h): the same steps, taps, comparisons and
// tie-breaking, in float (stored depth units) where the reference uses double (depth units).
// Where two candidates' heights differ by less than float rounding a pass may keep the other
// one; the cut then differs by about that rounding unless the different owner later loses or
// wins differently. tests/gl/gpu_cone_field_gl_test.cpp measures both.
#include <array>
#include <string>

#include "cutaway/cut_surface/gpu_cone_transform.h"
#include "gl/uniforms.h"

namespace cutaway::pipeline {
namespace {

constexpr int group_x = 64, group_y = 4;  // jump_flood.comp's local size (GROUP_X, GROUP_Y)

gl::ShaderDefines group_defines() { return {{"GROUP_X", std::to_string(group_x)}, {"GROUP_Y", std::to_string(group_y)}}; }

class GpuJumpFlooding final : public GpuConeTransform {
public:
    GpuJumpFlooding(const gl::ShaderLibrary& shaders, cone_field::JfaVariant variant)
        : init_(shaders, "cut_surface/jump_flood.comp", group_defines()),
          pass_(shaders.build({{GL_COMPUTE_SHADER, "cut_surface/jump_flood.comp"}}, group_defines())),
          resolve_(shaders.build({{GL_VERTEX_SHADER, "post/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "cut_surface/cone_resolve.frag"}},
                                 {{"JUMP_FLOODING", ""}})),
          variant_(variant) {}

    void run(const GpuConeInput& in, const CutTargets& targets) override {
        const int width = targets.depth.width(), height = targets.depth.height();
        if (owners_[0].width() != width || owners_[0].height() != height)
            for (gl::Texture& owners : owners_) owners = gl::Texture(GL_TEXTURE_2D, GL_RG32UI, width, height);
        const unsigned groups_x = group_count(width, group_x), groups_y = group_count(height, group_y);

        const gl::Program& init = init_.prepare(in);
        glBindImageTexture(0, owners_[0].id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RG32UI);
        init.use();
        glDispatchCompute(groups_x, groups_y, 1);

        int current = 0;
        gl::set_uniform(pass_, "slope", in.slope);
        pass_.use();
        for (const int step : cone_field::jfa_steps(variant_, width, height)) {
            glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
            gl::set_uniform(pass_, "step_size", step);
            glBindImageTexture(1, owners_[std::size_t(current)].id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RG32UI);
            glBindImageTexture(0, owners_[std::size_t(1 - current)].id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RG32UI);
            glDispatchCompute(groups_x, groups_y, 1);
            current = 1 - current;
        }

        gl::set_uniform(resolve_, "owners", 0);
        gl::set_uniform(resolve_, "slope", in.slope);
        owners_[std::size_t(current)].bind(0);
        write_cut_depth(resolve_, targets);
    }

private:
    SeedInitPrograms init_;
    gl::Program pass_, resolve_;
    cone_field::JfaVariant variant_;
    std::array<gl::Texture, 2> owners_;  ///< ping-pong, resized with the targets
};

}  // namespace

std::unique_ptr<GpuConeTransform> make_gpu_jump_flooding(const gl::ShaderLibrary& shaders, cone_field::JfaVariant variant) {
    return std::make_unique<GpuJumpFlooding>(shaders, variant);
}

}  // namespace cutaway::pipeline

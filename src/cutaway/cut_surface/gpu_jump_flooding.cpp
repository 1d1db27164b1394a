// Jump flooding on the GPU: one compute pass per step (jfa_steps), ping-ponging two RGBA32UI
// images of owners (seed position and stored depth per pixel, 2 pixels per texel,
// shaders/cut_surface/jump_flood.comp);
// the last pass stores each owner cone's height into a buffer, which reaches the cut depth by a
// pixel transfer or a fragment pass, whichever the device does faster (BufferedCutWrite,
// gpu_cone_transform.h). On llvmpipe, image
// loads with "0 = no owner" (out-of-image loads read 0: no bounds tests) and selects instead of
// branches made a pass much faster than texelFetch with branches (same run, loaded machine).
// Work groups of 64 x 4 passed JFA^2's 22 passes faster than 8 x 8 (16 x 16: slower, 32 x 8:
// the same); shader storage buffers instead of the images (a select for outside taps) were slower
// (zaphirus, 1920x1080, two alternating runs each, LP_NUM_THREADS=2, issue 16). The same pass as
// a fragment shader (full-screen triangle into an RG32UI attachment, texelFetch with clamped taps)
// was much slower than the compute passes over sapphire's 11 passes; 128 x 8, 32 x 32 and
// 8 x 8 groups were within noise of 64 x 4 (1920x1080, LP_NUM_THREADS=2).
//
// Each invocation floods a texel of 2 horizontally adjacent pixels in 2 rows a step apart: their
// 36 taps are 12 loads of 2 pixels and the 4 pixels are 2 stores. A step of 2k keeps a pixel's
// taps in the same half of texels k apart, so the packing holds for every step (a step of 1
// reads the texels beside). Where a row has no partner a step further (the last partial span),
// a dispatch of its own floods it alone, so no invocation is wasted.
// On llvmpipe a pass is bound by its image loads and stores, not by the cone arithmetic (passes
// without the square root or without any height took as long), and a store costs several times
// a load whatever its size (4 stores to one pixel took as long as to 4 pixels). Against the
// layout before, one RG32UI texel per pixel and 2 x 2 blocks of pixels a step apart (16 loads
// and 4 stores per 4 pixels), the present one made GPU jfa and jfa2 faster (BM_cpu_path,
// opharine 0.1%, 1920x1080, alternating processes, LP_NUM_THREADS=2). The 2 x 2 blocks had made
// a small step's pass faster than one pixel per invocation. Slower: one row per invocation
// (4.5 loads per pixel; jfa2's stage 1), 4 rows (more live values than registers), 4 x 2 pixel
// blocks in the one-pixel layout, several small steps fused in shared memory, and a first pass
// reading the seed image instead of an init pass's owners (texelFetch of the depth texture with
// bounds tests costs more than image loads).
//
// Against the CPU reference (cone_field/jump_flooding.h): the same steps, taps, comparisons and
// tie-breaking, in float (stored depth units) where the reference uses double (depth units).
// Where two candidates' heights differ by less than float rounding a pass may keep the other
// one; the cut then differs by about that rounding unless the different owner later loses or
// wins differently. tests/gl/gpu_cone_field_gl_test.cpp measures both.
#include <array>
#include <bit>
#include <string>
#include <vector>

#include "cutaway/cut_surface/cut_strategy_choice.h"
#include "cutaway/cut_surface/gpu_cone_transform.h"
#include "cutaway/cut_surface/jump_flood_split.h"
#include "gl/float_image_buffer.h"
#include "gl/uniforms.h"

namespace cutaway::pipeline {
namespace {

constexpr int group_x = 64, group_y = 4;  // jump_flood.comp's local size (GROUP_X, GROUP_Y)

gl::ShaderDefines group_defines() { return {{"GROUP_X", std::to_string(group_x)}, {"GROUP_Y", std::to_string(group_y)}}; }

/// A flooding pass's programs by block: 1 or 2 rows. `last`: the last pass's, storing the cut
/// instead of owners (CUT_OUT).
class BlockPrograms {
public:
    BlockPrograms(const gl::ShaderLibrary& shaders, bool last) : programs_{build(shaders, last, 1), build(shaders, last, 2)} {}
    const gl::Program& of(bool paired_y) const { return programs_[std::size_t(paired_y)]; }

private:
    static gl::Program build(const gl::ShaderLibrary& shaders, bool last, int block_y) {
        gl::ShaderDefines defines = group_defines();
        defines.push_back({"BLOCK_Y", std::to_string(block_y)});
        if (last) defines.push_back({"CUT_OUT", ""});
        return shaders.build({{GL_COMPUTE_SHADER, "cut_surface/jump_flood.comp"}}, defines);
    }
    std::array<gl::Program, 2> programs_;
};

/// Texels of the owners image per row: 2 pixels each.
int owner_columns(int width) { return (width + 1) / 2; }

/// One flooding pass of `step`: a dispatch per region of jump_flood_regions.
void flood(const BlockPrograms& programs, int step, float slope, int width, int height) {
    for (const JumpFloodRegion& region : jump_flood_regions(owner_columns(width), height, step)) {
        const gl::Program& program = programs.of(region.paired_y);
        gl::set_uniform(program, "slope", slope);
        gl::set_uniform(program, "width", width);
        gl::set_uniform(program, "step_log2", std::countr_zero(unsigned(step)));
        gl::set_uniform(program, "origin", region.origin);
        gl::set_uniform(program, "invocations", region.invocations);
        program.use();
        glDispatchCompute(group_count(region.invocations.x, group_x), group_count(region.invocations.y, group_y), 1);
    }
}

class GpuJumpFlooding final : public GpuConeTransform {
public:
    GpuJumpFlooding(const gl::ShaderLibrary& shaders, cone_field::JfaVariant variant, BufferedCutWrite write)
        : init_(shaders, "cut_surface/jump_flood.comp", group_defines()),
          passes_(shaders, false),
          last_passes_(shaders, true),
          variant_(variant),
          write_(write) {
        if (write_ == BufferedCutWrite::fragment_pass)
            cut_writer_ = shaders.build({{GL_VERTEX_SHADER, "post/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "cut_surface/cut_from_buffer.frag"}});
    }

    void run(const GpuConeInput& in, const CutTargets& targets) override {
        const int width = targets.depth.width(), height = targets.depth.height();
        if (owners_[0].width() != owner_columns(width) || owners_[0].height() != height) {
            for (gl::Texture& owners : owners_) owners = gl::Texture(GL_TEXTURE_2D, GL_RGBA32UI, owner_columns(width), height);
            cut_.resize(width, height);
        }

        const gl::Program& init = init_.prepare(in);
        gl::set_uniform(init, "width", width);
        glBindImageTexture(0, owners_[0].id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32UI);
        init.use();
        glDispatchCompute(group_count(owner_columns(width), group_x), group_count(height, group_y), 1);

        const std::vector<int> steps = cone_field::jfa_steps(variant_, width, height);
        int current = 0;
        for (std::size_t i = 0; i < steps.size(); ++i) {
            const bool last = i + 1 == steps.size();
            glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
            glBindImageTexture(1, owners_[std::size_t(current)].id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32UI);
            if (last)
                cut_.bind_image(0, GL_WRITE_ONLY);
            else
                glBindImageTexture(0, owners_[std::size_t(1 - current)].id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32UI);
            flood(last ? last_passes_ : passes_, steps[i], in.slope, width, height);
            current = 1 - current;
        }
        write_cut(targets, width);  // on the GL side: nothing read back
    }

private:
    void write_cut(const CutTargets& targets, int width) const {
        if (write_ == BufferedCutWrite::pixel_transfer) {
            cut_.write_depth(targets.depth);
            return;
        }
        cut_.bind_image(0, GL_READ_ONLY);
        gl::set_uniform(cut_writer_, "width", width);
        write_cut_depth(cut_writer_, targets);
    }

    SeedInitPrograms init_;
    BlockPrograms passes_, last_passes_;
    cone_field::JfaVariant variant_;
    BufferedCutWrite write_;
    gl::Program cut_writer_;             ///< cut_surface/cut_from_buffer.frag, for BufferedCutWrite::fragment_pass
    std::array<gl::Texture, 2> owners_;  ///< ping-pong, resized with the targets
    gl::FloatImageBuffer cut_;           ///< the last pass's cut, written into the cut depth image by write_
};

}  // namespace

BufferedCutWrite buffered_cut_write_for(std::string_view gl_renderer) {
    return is_software_rasteriser(gl_renderer) ? BufferedCutWrite::pixel_transfer : BufferedCutWrite::fragment_pass;
}

std::unique_ptr<GpuConeTransform> make_gpu_jump_flooding(const gl::ShaderLibrary& shaders, cone_field::JfaVariant variant,
                                                         BufferedCutWrite write) {
    return std::make_unique<GpuJumpFlooding>(shaders, variant, write);
}

}  // namespace cutaway::pipeline

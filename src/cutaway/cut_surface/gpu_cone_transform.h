#pragma once
// Cone-field transforms on the GPU (SPEC section 2, "Alternative cut surfaces"): the seed image
// stays on the GPU, the transform runs as compute passes over textures, and the cut is written
// into CutTargets::depth, with nothing read back. Everything is in the cut's stored depth units
// t = (s - near) / (far - near) of the cut camera: a cone z(q) - m |q - p| in depth units is
// t(q) - (m / (far - near)) |q - p| in stored units, and the clamp "0 at or in front of the near
// plane" (storable_cut_depth) is max(t, 0).
#include <memory>
#include <string_view>

#include "cone_field/chamfer.h"
#include "cone_field/jump_flooding.h"
#include "cutaway/frame_targets.h"
#include "gl/compute_dispatch.h"
#include "gl/shader_library.h"

namespace cutaway::pipeline {

struct GpuConeInput {
    const gl::Texture& seeds;  ///< GL_DEPTH_COMPONENT32F, stored units t, 0 = no seed; the targets' size
    bool widen_seeds = false;  ///< take the max over each pixel's 3x3 neighbourhood first (geometry seeds)
    float slope = 0;           ///< cone slope, stored units per pixel, > 0
};

class GpuConeTransform {
public:
    virtual ~GpuConeTransform() = default;
    /// Writes the cut into targets.depth (every pixel; 0 where no cone reaches).
    virtual void run(const GpuConeInput& input, const CutTargets& targets) = 0;
};

/// How jump flooding's cut, which its last pass stores in a buffer (gl/float_image_buffer.h),
/// reaches CutTargets::depth: a pixel transfer from the buffer, or a full-screen fragment pass
/// that reads it and sets gl_FragDepth (shaders/cut_surface/cut_from_buffer.frag). Same image.
enum class BufferedCutWrite { pixel_transfer, fragment_pass };

/// The cheaper of the two on the device GL_RENDERER names (sapphire, 1920x1080, glFinish laps):
/// on llvmpipe the transfer; on NVIDIA's H200 the fragment pass, where the transfer cost more and
/// also made the last flooding pass, which writes the buffer, far slower (stage 1 of jfa).
BufferedCutWrite buffered_cut_write_for(std::string_view gl_renderer);

/// Jump flooding with the passes of `variant` (jfa_steps), the CPU reference's 9-tap rule and
/// tie-breaking, in float instead of double; its cut written into the depth image by `write`.
std::unique_ptr<GpuConeTransform> make_gpu_jump_flooding(const gl::ShaderLibrary& shaders, cone_field::JfaVariant variant,
                                                         BufferedCutWrite write);

/// Chamfer propagation with `mask` as directional line sweeps (gpu_chamfer.cpp).
std::unique_ptr<GpuConeTransform> make_gpu_chamfer(const gl::ShaderLibrary& shaders, cone_field::ChamferMask mask);

/// The INIT variant of a transform's compute shader (first pass, from the seed image) with and
/// without WIDEN_SEEDS (cone_seed.glsl).
class SeedInitPrograms {
public:
    /// `defines`: the shader's own (e.g. its work group size), added to INIT and WIDEN_SEEDS.
    SeedInitPrograms(const gl::ShaderLibrary& shaders, const char* compute_shader, const gl::ShaderDefines& defines = {});
    /// The variant for `input`, its `seeds` uniform set and the seed texture bound to unit 0.
    const gl::Program& prepare(const GpuConeInput& input) const;

private:
    gl::Program plain_, widened_;
};

using gl::group_count;

/// Writes targets.depth from `program`, a full-screen fragment pass that sets gl_FragDepth
/// (shaders/cut_surface/cone_resolve.frag): depth test on with GL_ALWAYS, so every pixel is
/// written. Leaves the depth function at GL_LESS.
void write_cut_depth(const gl::Program& program, const CutTargets& targets);

}  // namespace cutaway::pipeline

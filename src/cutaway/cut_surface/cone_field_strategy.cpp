#include "cutaway/cut_surface/cone_field_strategy.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

#include "cone_field/cone_slope.h"
#include "cutaway/cut_surface/cut_depth_image.h"
#include "cutaway/cut_surface/cut_seeds.h"
#include "cutaway/cut_surface/gpu_cone_transform.h"
#include "gl/gl_context.h"

namespace cutaway::pipeline {
namespace {

/// Seeds read back, the cut computed on the CPU by `cut`, uploaded.
class CpuConeFieldStrategy final : public CutSurfaceStrategy {
public:
    CpuConeFieldStrategy(const gl::ShaderLibrary& shaders, ConeFieldCut cut) : seeds_(shaders), cut_(std::move(cut)) {}

    void render(const CutSurfaceInputs& inputs, const CutTargets& targets) override {
        const cone_field::SeedImage seeds = seeds_.render(inputs);
        readback_bytes_ = seeds.depth.pixel_count() * sizeof(float);  // one DEPTH32F image
        write_cut_depth_texture(cone_field_cut_for(inputs, seeds, cut_), inputs.cut_camera, targets.depth);
    }
    std::size_t readback_bytes() const override { return readback_bytes_; }

private:
    CutSeedPass seeds_;
    ConeFieldCut cut_;
    std::size_t readback_bytes_ = 0;
};

/// Seeds and transform on the GPU, nothing read back.
class GpuConeFieldStrategy final : public CutSurfaceStrategy {
public:
    GpuConeFieldStrategy(const gl::ShaderLibrary& shaders, std::unique_ptr<GpuConeTransform> transform)
        : seeds_(shaders), transform_(std::move(transform)) {}

    void render(const CutSurfaceInputs& inputs, const CutTargets& targets) override {
        const gl::Texture& seeds = seeds_.render_on_gpu(inputs);
        const Camera& camera = inputs.cut_camera;
        const double slope = cut_cone_slope(inputs) / double(camera.far_plane - camera.near_plane);
        transform_->run({seeds, CutSeedPass::needs_widening(inputs), float(slope)}, targets);
    }

private:
    CutSeedPass seeds_;
    std::unique_ptr<GpuConeTransform> transform_;
};

bool has_seed(const cone_field::SeedImage& seeds) {
    return std::any_of(seeds.depth.pixels.begin(), seeds.depth.pixels.end(),
                       [](float depth) { return depth != cone_field::no_seed; });
}

}  // namespace

double cut_cone_slope(const CutSurfaceInputs& inputs) {
    // Clamp the angle, not its tangent: 90 degrees in float radians lies just above pi/2, where
    // tan is hugely negative (clamping that tangent made aperture 180 the steepest cone).
    const double angle = std::clamp(double(inputs.wall_angle_h_rad), std::atan(1e-4), std::atan(1e4));
    return cone_field::cone_slope_per_pixel(angle, double(inputs.cone_reference_depth), double(inputs.cut_camera.focal_px()));
}

cone_field::FloatImage cone_field_cut_for(const CutSurfaceInputs& inputs, const cone_field::SeedImage& seeds,
                                          const ConeFieldCut& cut) {
    if (!has_seed(seeds)) return cone_field::FloatImage(seeds.width(), seeds.height());
    cone_field::FloatImage image = cut(seeds, cut_cone_slope(inputs));
    for (float& depth : image.pixels) depth = storable_cut_depth(depth, inputs.cut_camera);
    return image;
}

CutSurfaceEntry cone_field_entry(std::string name, std::string why, ConeFieldCut cut) {
    return {std::move(name), "cpu", std::move(why),
            [cut](const gl::ShaderLibrary& shaders) { return std::make_unique<CpuConeFieldStrategy>(shaders, cut); }, cut};
}

CutSurfaceEntry chamfer_entry(std::string name, cone_field::ChamferMask mask) {
    return {std::move(name), "gpu",
            "seeds and transform on the GPU, nothing read back: the raster passes become 1-D sweeps along every "
            "lattice line of each mask direction, one invocation per line (gpu_chamfer.cpp: equal to the raster "
            "passes up to float rounding)",
            [mask](const gl::ShaderLibrary& shaders) {
                return std::make_unique<GpuConeFieldStrategy>(shaders, make_gpu_chamfer(shaders, mask));
            },
            [mask](const cone_field::SeedImage& seeds, double slope) { return cone_field::chamfer_cut(seeds, slope, mask); }};
}

CutSurfaceEntry jump_flooding_entry(std::string name, cone_field::JfaVariant variant) {
    return {std::move(name), "gpu",
            "seeds and transform on the GPU, nothing read back: one compute pass per step over a texture of owners "
            "(seed position and depth per pixel), ping-ponged",
            [variant](const gl::ShaderLibrary& shaders) {
                return std::make_unique<GpuConeFieldStrategy>(
                    shaders, make_gpu_jump_flooding(shaders, variant, buffered_cut_write_for(gl::gl_renderer())));
            },
            [variant](const cone_field::SeedImage& seeds, double slope) {
                return cone_field::jump_flooding_cut(seeds, slope, variant);
            }};
}

}  // namespace cutaway::pipeline

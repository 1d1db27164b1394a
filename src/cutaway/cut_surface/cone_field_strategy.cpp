#include "cutaway/cut_surface/cone_field_strategy.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

#include "cutaway/cone_field/cone_slope.h"
#include "cutaway/cut_surface/cut_depth_image.h"
#include "cutaway/cut_surface/cut_seeds.h"

namespace cutaway::pipeline {
namespace {

class ConeFieldStrategy final : public CutSurfaceStrategy {
public:
    ConeFieldStrategy(const gl::ShaderLibrary& shaders, ConeFieldCut cut) : seeds_(shaders), cut_(std::move(cut)) {}

    void render(const CutSurfaceInputs& inputs, const CutTargets& targets) override {
        const cone_field::SeedImage seeds = seeds_.render(inputs);
        write_cut_depth_texture(cone_field_cut_for(inputs, seeds, cut_), inputs.cut_camera, targets.depth);
    }

private:
    CutSeedPass seeds_;
    ConeFieldCut cut_;
};

double median_seed_depth(const cone_field::SeedImage& seeds) {
    std::vector<float> depths;
    for (float depth : seeds.depth.pixels)
        if (depth != cone_field::no_seed) depths.push_back(depth);
    if (depths.empty()) throw std::invalid_argument("cone slope: the seed image holds no seed");
    const auto middle = depths.begin() + std::ptrdiff_t(depths.size() / 2);
    std::nth_element(depths.begin(), middle, depths.end());
    return *middle;
}

bool has_seed(const cone_field::SeedImage& seeds) {
    return std::any_of(seeds.depth.pixels.begin(), seeds.depth.pixels.end(),
                       [](float depth) { return depth != cone_field::no_seed; });
}

}  // namespace

double cut_cone_slope(const CutSurfaceInputs& inputs, const cone_field::SeedImage& seeds) {
    const double tangent = std::clamp(std::tan(double(inputs.aperture_h_rad)), 1e-4, 1e4);
    return cone_field::cone_slope_per_pixel(std::atan(tangent), median_seed_depth(seeds),
                                            double(inputs.cut_camera.focal_px()));
}

cone_field::FloatImage cone_field_cut_for(const CutSurfaceInputs& inputs, const cone_field::SeedImage& seeds,
                                          const ConeFieldCut& cut) {
    if (!has_seed(seeds)) return cone_field::FloatImage(seeds.width(), seeds.height());
    cone_field::FloatImage image = cut(seeds, cut_cone_slope(inputs, seeds));
    for (float& depth : image.pixels) depth = storable_cut_depth(depth, inputs.cut_camera);
    return image;
}

CutSurfaceEntry cone_field_entry(std::string name, std::string why, ConeFieldCut cut) {
    return {std::move(name), "cpu", std::move(why), [cut = std::move(cut)](const gl::ShaderLibrary& shaders) {
                return std::make_unique<ConeFieldStrategy>(shaders, cut);
            }};
}

CutSurfaceEntry chamfer_entry(std::string name, cone_field::ChamferMask mask) {
    return cone_field_entry(std::move(name),
                            "seeds on the GPU; the two chamfer raster passes run on the CPU because each pixel reads "
                            "values the same pass has just written (a sequential dependency)",
                            [mask](const cone_field::SeedImage& seeds, double slope) {
                                return cone_field::chamfer_cut(seeds, slope, mask);
                            });
}

CutSurfaceEntry jump_flooding_entry(std::string name, cone_field::JfaVariant variant) {
    return cone_field_entry(std::move(name),
                            "seeds on the GPU; the jump-flooding passes run on the CPU reference implementation "
                            "(each pass is data-parallel and suits a fragment shader, but that GPU version is "
                            "future work)",
                            [variant](const cone_field::SeedImage& seeds, double slope) {
                                return cone_field::jump_flooding_cut(seeds, slope, variant);
                            });
}

}  // namespace cutaway::pipeline

// The CPU caster's ray march against analytic results: trilinear sampling, opacity correction,
// early termination, and empty-space skipping taking the same samples as the naive loop.
#include <gtest/gtest.h>

#include <cmath>

#include "volume/cpu_ray_caster.h"
#include "volume/image_compare.h"
#include "volume/ray_march.h"

namespace cutaway::volume {
namespace {

QuantisedVolume uniform_volume(int n, std::uint8_t level) {
    QuantisedVolume volume;
    volume.dims = {n, n, n};
    volume.levels.assign(volume.dims.count(), level);
    return volume;
}

TEST(RayMarch, TrilinearSamplingHitsVoxelCentresAndAveragesBetween) {
    QuantisedVolume volume = uniform_volume(4, 0);
    volume.levels[1] = 100;  // (i 0, x 0, t 1)
    EXPECT_FLOAT_EQ(sample_level(volume, {1.5f, 0.5f, 0.5f}), 100);
    EXPECT_FLOAT_EQ(sample_level(volume, {1.0f, 0.5f, 0.5f}), 50);
    EXPECT_FLOAT_EQ(sample_level(volume, {1.5f, 0.0f, 0.0f}), 100);  // clamp to edge
}

TEST(RayMarch, JitterIsAFractionOfAStepThatVariesByPixel) {
    float previous = -1;
    for (std::uint32_t x = 0; x < 64; ++x) {
        const float f = jitter_fraction(x, 3);
        EXPECT_GE(f, 0.0f);
        EXPECT_LT(f, 1.0f);
        EXPECT_NE(f, previous);
        previous = f;
    }
}

/// Opacity after a straight ray of `length` voxels through a uniform volume.
float opacity_through(const VolumeScene& scene, float step, bool correction, float length) {
    RayCastSettings settings;
    settings.step = step;
    settings.opacity_correction = correction;
    settings.early_termination = false;
    settings.jitter = false;
    return march_ray(scene, settings, {0.5f, 8, 8}, {0.5f + length, 8, 8}, 0).alpha;
}

TEST(RayMarch, OpacityCorrectionMakesOpacityIndependentOfTheStep) {
    const QuantisedVolume volume = uniform_volume(16, 255);
    TransferFunctionSettings tf;
    tf.opacity = 0.1;  // per voxel
    const VolumeScene scene = make_scene(volume, build_transfer_table(tf), 4);
    const float expected = 1 - std::pow(0.9f, 12.0f);  // 12 voxels
    // Samples at 0, s, 2s, ... < 12: exactly 12 / s samples, each 1 - 0.9^s.
    EXPECT_NEAR(opacity_through(scene, 0.25f, true, 12), expected, 1e-4);
    EXPECT_NEAR(opacity_through(scene, 1.0f, true, 12), expected, 1e-4);
    // Without the correction a quarter step composites 48 samples of 0.1: 0.994 instead of 0.718.
    EXPECT_GT(opacity_through(scene, 0.25f, false, 12), expected + 0.25f);
}

TEST(RayMarch, EarlyTerminationStopsAtTheThreshold) {
    const QuantisedVolume volume = uniform_volume(16, 255);
    TransferFunctionSettings tf;
    tf.opacity = 0.5;
    const VolumeScene scene = make_scene(volume, build_transfer_table(tf), 4);
    RayCastSettings settings;
    settings.step = 1;
    settings.jitter = false;
    const RayResult ray = march_ray(scene, settings, {0.5f, 8, 8}, {15.5f, 8, 8}, 0);
    // 1 - 0.5^n >= 0.99 first at n = 7.
    EXPECT_EQ(ray.samples, 7u);
    EXPECT_GE(ray.alpha, 0.99f);
}

TEST(CpuCaster, SkippingTakesTheSameSamplesWhereTheyMatter) {
    // A volume empty under the layer highlight except a slab of high levels: skipping must give the
    // identical image (same sample positions, skipped samples have opacity 0) with fewer samples.
    QuantisedVolume volume = uniform_volume(32, 100);
    for (int i = 0; i < 32; ++i)
        for (int x = 0; x < 32; ++x)
            for (int t = 20; t < 24; ++t) volume.levels[(std::size_t(i) * 32 + std::size_t(x)) * 32 + std::size_t(t)] = 250;
    TransferFunctionSettings tf;
    tf.kind = TransferFunctionKind::layer;
    const VolumeScene scene = make_scene(volume, build_transfer_table(tf), 8);
    RayCastSettings settings;
    settings.width = settings.height = 64;
    settings.empty_space_skipping = false;
    const CastResult naive = cast_rays_cpu(scene, settings, 2);
    settings.empty_space_skipping = true;
    const CastResult skipping = cast_rays_cpu(scene, settings, 2);
    EXPECT_EQ(psnr_db(naive.image, skipping.image), std::numeric_limits<double>::infinity());
    EXPECT_EQ(naive.rays, skipping.rays);
    EXPECT_LT(2 * skipping.samples, naive.samples);
}

}  // namespace
}  // namespace cutaway::volume

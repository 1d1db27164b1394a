// GPU caster against the CPU reference (EGL on llvmpipe in CI; label "gl"). Images are 256x256 on
// a small synthetic cube so the suite stays quick on two cores.
#include <gtest/gtest.h>

#include <memory>

#include "gl/gl_context.h"
#include "gl/shader_library.h"
#include "volume/cpu_ray_caster.h"
#include "volume/gpu_ray_caster.h"
#include "volume/image_compare.h"
#include "volume/quantised_volume.h"
#include "volume_test_support.h"

namespace cutaway::test {
namespace {

using namespace cutaway::volume;

// The bar. The casters take the same sample positions and use the same table arithmetic;
// what differs is the entry point (rasterised interpolation vs a slab test, ~1e-4 voxel) and the
// GPU's trilinear filtering precision, a level or so on a few pixels.
constexpr double kMinPsnrDb = 40;

class VolumeGlCaster : public ::testing::Test {
protected:
    // Built by the first test that runs (an exception there fails that test; a failure in
    // SetUpTestSuite would only mark the tests skipped) and kept for the rest of the suite.
    void SetUp() override {
        if (volume_) return;
        context_ = gl::create_context(gl::ContextOptions{}).release();
        const ScratchDir scratch = unique_scratch("volume-gl");
        volume_ = new QuantisedVolume(quantise(write_and_load(scratch, "synthetic.sgy", synthetic_volume(40, 36, 64))));
    }
    static void TearDownTestSuite() {
        delete volume_;
        delete context_;
        volume_ = nullptr;
        context_ = nullptr;
    }

    static RayCastSettings small_frame() {
        RayCastSettings settings;
        settings.width = settings.height = 256;
        return settings;
    }

    static CastResult gpu(const VolumeScene& scene, const RayCastSettings& settings) {
        const gl::ShaderLibrary shaders(gl::ShaderLibrary::default_root());
        GpuRayCaster caster(shaders, scene);
        gl::StageTimer timer;
        return caster.render(settings, timer);
    }

    static VolumeScene scene(TransferFunctionKind kind) {
        TransferFunctionSettings tf;
        tf.kind = kind;
        return make_scene(*volume_, build_transfer_table(tf), small_frame().block_size);
    }

    static inline gl::GlContext* context_ = nullptr;
    static inline QuantisedVolume* volume_ = nullptr;
};

TEST_F(VolumeGlCaster, GpuMatchesCpuForEveryTransferFunction) {
    for (TransferFunctionKind kind : {TransferFunctionKind::grey, TransferFunctionKind::pseudo, TransferFunctionKind::layer}) {
        SCOPED_TRACE(transfer_function_name(kind));
        const VolumeScene s = scene(kind);
        const CastResult on_gpu = gpu(s, small_frame());
        const CastResult on_cpu = cast_rays_cpu(s, small_frame(), 2);
        EXPECT_GE(psnr_db(on_gpu.image, on_cpu.image), kMinPsnrDb);
        // Same rays and (up to edge pixels and near-tie terminations) the same samples: 1%.
        EXPECT_NEAR(double(on_gpu.rays), double(on_cpu.rays), 0.01 * double(on_cpu.rays));
        EXPECT_NEAR(double(on_gpu.samples), double(on_cpu.samples), 0.01 * double(on_cpu.samples));
        EXPECT_GT(on_cpu.rays, 10000u);  // the cube fills a good part of the 65536 pixels
    }
}

TEST_F(VolumeGlCaster, EverySwitchOffStillMatchesCpu) {
    RayCastSettings settings = small_frame();
    settings.opacity_correction = settings.jitter = settings.early_termination = settings.empty_space_skipping = false;
    settings.step = 1;
    const VolumeScene s = scene(TransferFunctionKind::pseudo);
    EXPECT_GE(psnr_db(gpu(s, settings).image, cast_rays_cpu(s, settings, 2).image), kMinPsnrDb);
}

TEST_F(VolumeGlCaster, SkippingHalvesTheSamplesOfLayerHighlightWithTheSameImage) {
    const VolumeScene s = scene(TransferFunctionKind::layer);
    RayCastSettings naive = small_frame();
    naive.empty_space_skipping = false;
    const CastResult without = gpu(s, naive);
    const CastResult with = gpu(s, small_frame());
    EXPECT_GE(psnr_db(without.image, with.image), kMinPsnrDb);
    EXPECT_GE(double(without.samples), 2.0 * double(with.samples))
        << "naive " << without.samples << ", skipping " << with.samples << " (occupied blocks "
        << s.occupied_fraction() << ")";
}

TEST_F(VolumeGlCaster, RealF3CropMatchesCpu) {
    const QuantisedVolume f3 = quantise(load_segy(segy_file("f3.sgy")));
    TransferFunctionSettings tf;
    tf.kind = TransferFunctionKind::pseudo;
    const VolumeScene s = make_scene(f3, build_transfer_table(tf), 8);
    EXPECT_GE(psnr_db(gpu(s, small_frame()).image, cast_rays_cpu(s, small_frame(), 2).image), kMinPsnrDb);
}

}  // namespace
}  // namespace cutaway::test

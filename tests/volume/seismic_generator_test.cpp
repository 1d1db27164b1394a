// The synthetic seismic generator: determinism, the wavelet, sizes and refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "generators/seismic_model.h"

namespace cutaway::generators {
namespace {

SeismicParameters small(std::uint64_t seed) {
    SeismicParameters p;
    p.inlines = 8;
    p.crosslines = 9;
    p.samples = 40;
    p.seed = seed;
    return p;
}

TEST(SeismicGenerator, SameSeedSameCubeOtherSeedOtherCube) {
    const SeismicVolume a = generate_seismic(small(3));
    EXPECT_EQ(a.amplitudes, generate_seismic(small(3)).amplitudes);
    EXPECT_NE(a.amplitudes, generate_seismic(small(4)).amplitudes);
    EXPECT_EQ(a.amplitudes.size(), 8u * 9u * 40u);
}

TEST(SeismicGenerator, RickerPeaksAtOneAndCrossesZeroWhereTheFormulaSays) {
    EXPECT_DOUBLE_EQ(ricker(30, 0), 1.0);
    const double zero = 1 / (std::numbers::sqrt2 * std::numbers::pi * 30);
    EXPECT_NEAR(ricker(30, zero), 0.0, 1e-12);
    EXPECT_LT(ricker(30, 2 * zero), 0.0);
}

TEST(SeismicGenerator, NoiseFreeCubeIsTheWaveletTimesTheReflectivity) {
    SeismicParameters p = small(5);
    p.noise_fraction = 0;
    p.faults = 0;
    p.horizons = 1;
    p.horizon_relief_samples = 0;
    const SeismicVolume volume = generate_seismic(p);
    // One flat horizon: every trace is the same scaled wavelet, largest at the horizon's sample.
    for (int x = 1; x < p.crosslines; ++x)
        for (int t = 0; t < p.samples; ++t) EXPECT_FLOAT_EQ(volume.amplitudes[volume.index(0, x, t)], volume.amplitudes[volume.index(0, 0, t)]);
}

TEST(SeismicGenerator, PresetsHoldThePaperSizesAndTheGrowthSeries) {
    EXPECT_EQ(find_seismic_preset("paper-500").samples, 500);
    EXPECT_EQ(find_seismic_preset("paper-250").inlines, 101);
    for (int step = 1; step <= 10; ++step) {
        const SeismicParameters p = growth_step(step);
        EXPECT_EQ(p.inlines, 10 * step);
        EXPECT_EQ(p.crosslines, 28 * step);
        EXPECT_EQ(p.samples, 25 * step);
    }
    EXPECT_THROW(find_seismic_preset("nope"), std::invalid_argument);
}

/// The message generate_seismic refuses `p` with ("" if it accepts it).
std::string refusal(const SeismicParameters& p) {
    try {
        generate_seismic(p);
    } catch (const std::invalid_argument& error) {
        return error.what();
    }
    return "";
}

TEST(SeismicGenerator, RefusesBadParametersNamingTheField) {
    SeismicParameters p = small(1);
    p.fault_dip_deg = 10;
    EXPECT_NE(refusal(p).find("--dip: expected a dip in [30, 90] degrees, found '10'"), std::string::npos) << refusal(p);
    p = small(1);
    p.inlines = 5000;
    p.crosslines = 5000;
    p.samples = 1000;  // 100 GB of samples
    EXPECT_NE(refusal(p).find("--dims: expected a cube within the memory limit"), std::string::npos) << refusal(p);
}

}  // namespace
}  // namespace cutaway::generators

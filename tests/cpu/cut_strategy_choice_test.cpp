// "auto" picks frustum-sweep from a threshold that depends on the kind of GL device
// (cut_strategy_choice.h): the crossover of the two strategies' stage 1 times measured on each.
#include <gtest/gtest.h>

#include "cutaway/cut_surface/cut_strategy_choice.h"

namespace cutaway::test {
namespace {

using namespace pipeline;

TEST(CutStrategyChoice, SoftwareRasterisersAreToldApartFromGpusByTheirRendererString) {
    EXPECT_TRUE(is_software_rasteriser("llvmpipe (LLVM 15.0.6, 256 bits)"));
    EXPECT_TRUE(is_software_rasteriser("softpipe"));
    EXPECT_TRUE(is_software_rasteriser("Google SwiftShader"));
    EXPECT_FALSE(is_software_rasteriser("NVIDIA H100 80GB HBM3/PCIe/SSE2"));
    EXPECT_FALSE(is_software_rasteriser("AMD Radeon RX 7900 XTX (radeonsi, navi31, LLVM 15.0.6, DRM 3.54)"));
    EXPECT_EQ(auto_sweep_from_primaries("llvmpipe (LLVM 15.0.6, 256 bits)"), auto_sweep_from_primaries_on_cpu);
    EXPECT_EQ(auto_sweep_from_primaries("NVIDIA H200/PCIe/SSE2"), auto_sweep_from_primaries_on_gpu);
    EXPECT_LT(auto_sweep_from_primaries_on_cpu, auto_sweep_from_primaries_on_gpu);
}

TEST(CutStrategyChoice, AutoSwitchesToTheSweepAtTheThresholdAndNamedStrategiesStayAsAskedFor) {
    EXPECT_EQ(resolve_cut_strategy(auto_cut_strategy, 499, 500), "frustum-clusters");
    EXPECT_EQ(resolve_cut_strategy(auto_cut_strategy, 500, 500), "frustum-sweep");
    EXPECT_EQ(resolve_cut_strategy(auto_cut_strategy, 9999, 10000), "frustum-clusters");
    EXPECT_EQ(resolve_cut_strategy("frustum", 1000000, 500), "frustum");
    EXPECT_EQ(resolve_cut_strategy("jfa2", 0, 500), "jfa2");
    EXPECT_NE(auto_choice_rule(500).find("500"), std::string::npos);
}

}  // namespace
}  // namespace cutaway::test

// Parameters that cannot give a model are refused before any work, with a message that names
// the parameter and the value.
#include <gtest/gtest.h>

#include <functional>
#include <stdexcept>

#include "generator_test_support.h"

namespace cutaway::generators {
namespace {

struct BadCase {
    const char* name;
    std::function<void(GeneratorParameters&)> spoil;
    const char* message;  ///< part of the error text
};

class BadParameters : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadParameters, RefusedWithClearMessage) {
    GeneratorParameters p = testing::small_parameters();
    GetParam().spoil(p);
    try {
        testing::generate_quietly(p);
        FAIL() << "accepted " << GetParam().name;
    } catch (const std::invalid_argument& error) {
        EXPECT_NE(std::string(error.what()).find(GetParam().message), std::string::npos) << error.what();
    }
}

INSTANTIATE_TEST_SUITE_P(
    Generator, BadParameters,
    ::testing::Values(
        BadCase{"zero_nx", [](GeneratorParameters& p) { p.dims.nx = 0; }, "dims must be positive"},
        BadCase{"negative_nz", [](GeneratorParameters& p) { p.dims.nz = -3; }, "dims must be positive"},
        BadCase{"throw_above_thickness", [](GeneratorParameters& p) { p.throw_range = {10, 500}; },
                "larger than the model"},
        BadCase{"throw_min_above_max", [](GeneratorParameters& p) { p.throw_range = {20, 10}; }, "throw range"},
        BadCase{"pinch_fraction_above_one", [](GeneratorParameters& p) { p.pinch_out_fraction = 1.5; },
                "pinch-out fraction must lie in [0, 1)"},
        BadCase{"inactive_fraction_negative", [](GeneratorParameters& p) { p.inactive_fraction = -0.1; },
                "inactive fraction must lie in [0, 1)"},
        BadCase{"fractions_sum_to_one", [](GeneratorParameters& p) { p.inactive_fraction = p.pinch_out_fraction = 0.5; },
                "below 1"},
        BadCase{"porosity_mean_one", [](GeneratorParameters& p) { p.poro_mean = 1; }, "porosity mean"},
        BadCase{"zero_thickness", [](GeneratorParameters& p) { p.thickness = 0; }, "thickness must be positive"},
        BadCase{"flat_fault", [](GeneratorParameters& p) { p.fault_dip_deg = 5; }, "fault dip"},
        BadCase{"beyond_memory_limit", [](GeneratorParameters& p) { p.dims = {3000, 3000, 100}; },
                "beyond the memory limit"}),
    [](const ::testing::TestParamInfo<BadCase>& info) { return std::string(info.param.name); });

TEST(GeneratorMemory, EstimateOfTenMillionCellsFitsFourGigabytes) {
    EXPECT_LT(estimated_peak_bytes(find_preset("scale-10m")), kDefaultGeneratorMemoryLimit);
}

}  // namespace
}  // namespace cutaway::generators

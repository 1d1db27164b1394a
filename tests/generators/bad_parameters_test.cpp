// Parameters that cannot give a model are refused before any work, in the form of every option
// error ("--option: expected ..., found 'VALUE'"): the option that sets the parameter, its range,
// the value.
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
        BadCase{"zero_nx", [](GeneratorParameters& p) { p.dims.nx = 0; }, "--dims: expected NX NY NZ, each at least 1"},
        BadCase{"negative_nz", [](GeneratorParameters& p) { p.dims.nz = -3; }, "--dims: expected NX NY NZ, each at least 1"},
        BadCase{"throw_above_thickness", [](GeneratorParameters& p) { p.throw_range = {10, 500}; },
                "--throw: expected MAX below the model's thickness"},
        BadCase{"throw_min_above_max", [](GeneratorParameters& p) { p.throw_range = {20, 10}; }, "--throw: expected MIN MAX in metres with 0 <= MIN <= MAX, found '20 10'"},
        BadCase{"pinch_fraction_above_one", [](GeneratorParameters& p) { p.pinch_out_fraction = 1.5; },
                "--pinch-fraction: expected a share of the cells in [0, 1), found '1.5'"},
        BadCase{"inactive_fraction_negative", [](GeneratorParameters& p) { p.inactive_fraction = -0.1; },
                "--inactive-fraction: expected a share of the cells in [0, 1), found '-0.1'"},
        BadCase{"fractions_sum_to_one", [](GeneratorParameters& p) { p.inactive_fraction = p.pinch_out_fraction = 0.5; },
                "--pinch-fraction + --inactive-fraction: expected a sum below 1"},
        BadCase{"porosity_mean_one", [](GeneratorParameters& p) { p.poro_mean = 1; }, "--poro-mean: expected a porosity mean in (0, 1), found '1'"},
        BadCase{"zero_thickness", [](GeneratorParameters& p) { p.thickness = 0; }, "--extent: expected a positive thickness in metres, found '0'"},
        BadCase{"flat_fault", [](GeneratorParameters& p) { p.fault_dip_deg = 5; }, "--dip: expected a dip in [30, 90] degrees from horizontal, found '5'"},
        BadCase{"beyond_memory_limit", [](GeneratorParameters& p) { p.dims = {3000, 3000, 100}; },
                "--memory-limit-gb: expected room for 900000000 cells"}),
    [](const ::testing::TestParamInfo<BadCase>& info) { return std::string(info.param.name); });

TEST(GeneratorMemory, EstimateOfTenMillionCellsFitsFourGigabytes) {
    EXPECT_LT(estimated_peak_bytes(find_preset("scale-10m")), kDefaultGeneratorMemoryLimit);
}

}  // namespace
}  // namespace cutaway::generators

// MODEL arguments (app_core/model_source.h): a preset asked for one static property skips the water
// flood, and every array it does generate is the same as the full model's, bit for bit.
#include <gtest/gtest.h>

#include "app_core/model_source.h"

namespace cutaway::app {
namespace {

constexpr std::size_t memory_limit = std::size_t(1) << 32;

TEST(ModelSource, PresetForOneStaticPropertySkipsSwatAndKeepsEveryOtherArray) {
    const LoadedModel full = load_model({"preset:zaphirus"}, memory_limit);
    const LoadedModel poro_only = load_model({"preset:zaphirus"}, memory_limit, std::string());
    ASSERT_NE(full.grid.dynamic_property("SWAT", 0), nullptr) << "the preset has SWAT steps";
    EXPECT_TRUE(poro_only.grid.dynamic_property_names().empty());
    EXPECT_EQ(full.grid.coord(), poro_only.grid.coord());
    EXPECT_EQ(full.grid.actnum(), poro_only.grid.actnum());
    for (std::size_t v = 0; v < full.grid.dims().zcorn_value_count(); ++v)
        ASSERT_EQ(full.grid.zcorn().value(v), poro_only.grid.zcorn().value(v)) << "ZCORN value " << v;
    for (const std::string& name : full.grid.property_names())
        EXPECT_EQ(*full.grid.property(name), *poro_only.grid.property(name)) << name;
    EXPECT_NE(poro_only.description.find("no SWAT steps"), std::string::npos) << poro_only.description;
}

TEST(ModelSource, PresetAskedForSwatKeepsItsSteps) {
    const LoadedModel swat = load_model({"preset:zaphirus"}, memory_limit, std::string("SWAT"));
    EXPECT_NE(swat.grid.dynamic_property("SWAT", 0), nullptr);
}

TEST(ModelSource, UnknownPresetNamesTheArgumentAndThePresets) {
    try {
        load_model({"preset:nope"}, memory_limit);
        FAIL() << "accepted preset:nope";
    } catch (const std::invalid_argument& error) {
        EXPECT_NE(std::string(error.what()).find("preset:nope: expected preset:NAME with NAME one of zaphirus"),
                  std::string::npos)
            << error.what();
    }
}

}  // namespace
}  // namespace cutaway::app

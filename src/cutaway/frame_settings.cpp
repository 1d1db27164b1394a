#include "cutaway/frame_settings.h"

#include "cutaway/setting_names.h"

namespace cutaway::pipeline {
namespace {

constexpr NamedChoice<BorderMode> border_modes[] = {{"raycast", BorderMode::raycast}, {"threshold", BorderMode::threshold}};
constexpr NamedChoice<MeanFilterKernel> mean_filter_kernels[] = {{"full", MeanFilterKernel::full},
                                                                 {"sampled", MeanFilterKernel::sampled},
                                                                 {"distance-scaled", MeanFilterKernel::distance_scaled}};
constexpr NamedChoice<OnlyLayer> only_layers[] = {
    {"both", OnlyLayer::both}, {"primaries", OnlyLayer::primaries}, {"secondaries", OnlyLayer::secondaries}};
constexpr NamedChoice<SeedSource> seed_sources[] = {{"boxes", SeedSource::boxes}, {"geometry", SeedSource::geometry}};
constexpr NamedChoice<DrawMode> draw_modes[] = {{"visible", DrawMode::visible}, {"all-faces", DrawMode::all_faces}};
constexpr NamedChoice<Stage2Passes> stage2_passes[] = {
    {"1", Stage2Passes::one}, {"2", Stage2Passes::two}, {"deferred", Stage2Passes::deferred}};
constexpr NamedChoice<ColourScale> colour_scales[] = {
    {"auto", ColourScale::automatic}, {"linear", ColourScale::linear}, {"log", ColourScale::log}};
constexpr NamedChoice<bool> on_off[] = {{"on", true}, {"off", false}};
constexpr NamedChoice<bool> ssao_resolutions[] = {{"half", true}, {"full", false}};
constexpr NamedChoice<bool> primary_sets[] = {{"property", true}, {"none", false}};

}  // namespace

ChoiceTable<BorderMode> choices_of(BorderMode) { return border_modes; }
ChoiceTable<MeanFilterKernel> choices_of(MeanFilterKernel) { return mean_filter_kernels; }
ChoiceTable<OnlyLayer> choices_of(OnlyLayer) { return only_layers; }
ChoiceTable<SeedSource> choices_of(SeedSource) { return seed_sources; }
ChoiceTable<DrawMode> choices_of(DrawMode) { return draw_modes; }
ChoiceTable<Stage2Passes> choices_of(Stage2Passes) { return stage2_passes; }
ChoiceTable<ColourScale> choices_of(ColourScale) { return colour_scales; }
ChoiceTable<bool> on_off_choices() { return on_off; }
ChoiceTable<bool> ssao_resolution_choices() { return ssao_resolutions; }
ChoiceTable<bool> primaries_choices() { return primary_sets; }

std::string joined_choices(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names) text += (text.empty() ? "" : "|") + name;
    return text;
}

const char* to_string(BorderMode mode) { return name_of_choice(choices_of(mode), mode); }
const char* to_string(MeanFilterKernel kernel) { return name_of_choice(choices_of(kernel), kernel); }
const char* to_string(SeedSource seeds) { return name_of_choice(choices_of(seeds), seeds); }
const char* to_string(DrawMode draw) { return name_of_choice(choices_of(draw), draw); }
const char* to_string(Stage2Passes passes) { return name_of_choice(choices_of(passes), passes); }
const char* to_string(ColourScale scale) { return name_of_choice(choices_of(scale), scale); }
const char* to_string(OnlyLayer only) { return name_of_choice(choices_of(only), only); }

}  // namespace cutaway::pipeline

#pragma once
// Each choice of a frame's settings named once: the command line checks its values against these
// tables while parsing (before any file is read), and to_string, stats.json, describe() and the
// viewer's lists all read the same table.
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "cutaway/frame_settings.h"

namespace cutaway::pipeline {

template <typename Value>
struct NamedChoice {
    const char* name;
    Value value;
};

template <typename Value>
using ChoiceTable = std::span<const NamedChoice<Value>>;

ChoiceTable<BorderMode> choices_of(BorderMode);
ChoiceTable<MeanFilterKernel> choices_of(MeanFilterKernel);
ChoiceTable<OnlyLayer> choices_of(OnlyLayer);
ChoiceTable<SeedSource> choices_of(SeedSource);
ChoiceTable<DrawMode> choices_of(DrawMode);
ChoiceTable<Stage2Passes> choices_of(Stage2Passes);
ChoiceTable<ColourScale> choices_of(ColourScale);

/// The two-way switches spelled as words on the command line.
ChoiceTable<bool> on_off_choices();           ///< --ssao, --contours: on|off
ChoiceTable<bool> ssao_resolution_choices();  ///< --ssao-resolution: half (true) | full
/// --primaries: property (true: chosen by --property's range or fraction, or --select-by) | none
ChoiceTable<bool> primaries_choices();

template <typename Value>
std::optional<Value> find_choice(ChoiceTable<Value> table, std::string_view name) {
    for (const NamedChoice<Value>& choice : table)
        if (name == choice.name) return choice.value;
    return std::nullopt;
}

template <typename Value>
const char* name_of_choice(ChoiceTable<Value> table, Value value) {
    for (const NamedChoice<Value>& choice : table)
        if (choice.value == value) return choice.name;
    return "unknown";
}

template <typename Value>
std::vector<std::string> choice_names(ChoiceTable<Value> table) {
    std::vector<std::string> names;
    for (const NamedChoice<Value>& choice : table) names.emplace_back(choice.name);
    return names;
}

/// The names of an enum's choices, in the table's order.
template <typename Enum>
std::vector<std::string> choice_names() {
    return choice_names(choices_of(Enum{}));
}

/// "a|b|c", as option messages and help list them.
std::string joined_choices(const std::vector<std::string>& names);

}  // namespace cutaway::pipeline

#include "cutaway/temporal/coherence.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace cutaway::temporal {
namespace {

constexpr std::pair<Coherence, const char*> coherence_table[] = {{Coherence::none, "none"},
                                                                 {Coherence::smooth, "smooth"}};

}  // namespace

std::vector<std::string> coherence_names() {
    std::vector<std::string> names;
    for (const auto& entry : coherence_table) names.emplace_back(entry.second);
    return names;
}

const char* to_string(Coherence coherence) {
    for (const auto& [value, name] : coherence_table)
        if (value == coherence) return name;
    return "unknown";
}

Coherence parse_coherence(const std::string& name) {
    std::string known;
    for (const auto& [value, text] : coherence_table) {
        if (name == text) return value;
        known.append(known.empty() ? "" : "|").append(text);
    }
    throw std::invalid_argument("--coherence '" + name + "': expected " + known);
}

StepBlend blend_at(const AnimationTimeline& timeline, std::size_t frame, Coherence coherence) {
    const std::size_t lower = timeline.first_step + frame / timeline.frames_per_step;
    const std::size_t within = frame % timeline.frames_per_step;
    if (coherence == Coherence::none || within == 0) return {lower, lower, 0.0f};
    return {lower, std::min(lower + 1, timeline.last_step), float(double(within) / double(timeline.frames_per_step))};
}

}  // namespace cutaway::temporal

#include "cutaway/temporal/paced_transition.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace cutaway::temporal {
namespace {

/// The limit a cell crosses from `from` to `to` when it enters (the range's limit on its side)
/// or leaves (the widened limit on the side it leaves by).
float crossed_limit(float from, float to, bool entering, const grid::PrimaryRange& range, float band) {
    if (entering) return from < range.min ? range.min : range.max;
    return to < range.min - band ? range.min - band : range.max + band;
}

}  // namespace

PacedTransition::PacedTransition(const std::vector<float>& lower, const std::vector<float>& upper,
                                 const std::vector<std::uint8_t>& was, const std::vector<std::uint8_t>& is,
                                 const grid::PrimaryRange& range, float band)
    : paced_(lower.size(), -1.0f), crossing_(lower.size(), 0.0f) {
    if (upper.size() != lower.size() || was.size() != lower.size() || is.size() != lower.size())
        throw std::invalid_argument("paced transition: expected values and flags of one size per step");
    std::vector<std::size_t> cells;
    for (std::size_t c = 0; c < lower.size(); ++c) {
        if ((was[c] != 0) == (is[c] != 0)) continue;
        const float limit = crossed_limit(lower[c], upper[c], is[c] != 0, range, band);
        const float span = upper[c] - lower[c];
        crossing_[c] = span != 0.0f ? std::clamp((limit - lower[c]) / span, 0.0f, 1.0f) : 0.5f;
        cells.push_back(c);
    }
    // Order of crossing, ties by cell index (deterministic); paced times evenly spread in (0, 1).
    std::stable_sort(cells.begin(), cells.end(), [&](std::size_t a, std::size_t b) { return crossing_[a] < crossing_[b]; });
    changing_ = cells.size();
    for (std::size_t rank = 0; rank < cells.size(); ++rank)
        paced_[cells[rank]] = float((double(rank) + 0.5) / double(cells.size()));
}

void PacedTransition::flags_at(float weight, const std::vector<std::uint8_t>& was, const std::vector<std::uint8_t>& is,
                               std::vector<std::uint8_t>& flags) const {
    flags.resize(was.size());
    for (std::size_t c = 0; c < was.size(); ++c) flags[c] = paced_[c] >= 0.0f && weight >= paced_[c] ? is[c] : was[c];
}

void PacedTransition::values_at(float weight, const std::vector<float>& lower, const std::vector<float>& upper,
                                std::vector<float>& values) const {
    values.resize(lower.size());
    for (std::size_t c = 0; c < lower.size(); ++c) {
        float g = weight;
        if (const float p = paced_[c]; p >= 0.0f) {
            const float x = crossing_[c];
            g = weight < p ? x * weight / p : x + (1.0f - x) * (weight - p) / (1.0f - p);
        }
        values[c] = (1.0f - g) * lower[c] + g * upper[c];
    }
}

}  // namespace cutaway::temporal

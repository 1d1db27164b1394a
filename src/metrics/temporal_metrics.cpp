#include "metrics/temporal_metrics.h"

#include <stdexcept>
#include <string>

#include "metrics/image_metrics.h"

namespace cutaway::metrics {
namespace {

void require_same_size(std::size_t before, std::size_t after, const char* what) {
    if (before != after)
        throw std::invalid_argument(std::string(what) + ": expected two frames of the same size, found " +
                                    std::to_string(before) + " and " + std::to_string(after));
}

}  // namespace

PopCounts count_pops(const std::vector<std::uint8_t>& before, const std::vector<std::uint8_t>& after) {
    require_same_size(before.size(), after.size(), "primary flags");
    PopCounts pops;
    for (std::size_t c = 0; c < after.size(); ++c) {
        const bool was = before[c] != 0, is = after[c] != 0;
        pops.in += is && !was;
        pops.out += was && !is;
    }
    return pops;
}

std::size_t PopReversals::count(const std::vector<std::uint8_t>& before, const std::vector<std::uint8_t>& after) {
    require_same_size(last_change_.size(), before.size(), "primary flags before");
    require_same_size(last_change_.size(), after.size(), "primary flags after");
    std::size_t reversals = 0;
    for (std::size_t c = 0; c < after.size(); ++c) {
        const bool was = before[c] != 0, is = after[c] != 0;
        if (was == is) continue;
        const std::int8_t change = is ? 1 : -1;
        reversals += last_change_[c] == -change;
        last_change_[c] = change;
    }
    return reversals;
}

std::vector<CutState> cut_states(const std::vector<std::uint32_t>& cell, const std::vector<std::uint32_t>& flags) {
    require_same_size(cell.size(), flags.size(), "cell ids and flags");
    std::vector<CutState> states(cell.size(), CutState::background);
    for (std::size_t i = 0; i < cell.size(); ++i)
        if (cell[i] != 0) states[i] = (flags[i] & flag_cut_fill) ? CutState::cut_away : CutState::kept;
    return states;
}

CutFlicker cut_flicker(const std::vector<CutState>& before, const std::vector<CutState>& after) {
    require_same_size(before.size(), after.size(), "cut states");
    CutFlicker flicker;
    for (std::size_t i = 0; i < after.size(); ++i) {
        if (before[i] == CutState::background && after[i] == CutState::background) continue;
        ++flicker.model_pixels;
        flicker.changed += before[i] != after[i];
    }
    flicker.fraction = flicker.model_pixels ? double(flicker.changed) / double(flicker.model_pixels) : 0.0;
    return flicker;
}

}  // namespace cutaway::metrics

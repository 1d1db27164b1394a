#include "cutaway/temporal/cell_openings.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace cutaway::temporal {

std::size_t frames_to_open(std::size_t frames_per_step) {
    return std::min(frames_per_step + 1, CellOpenings::max_frames_to_open);
}

float CellOpenings::depth_share(float frames_share, bool beside_cut) {
    return std::pow(frames_share, beside_cut ? 0.375f : 1.25f);
}

CellOpenings::CellOpenings(std::size_t frames_to_open, const grid::GridDims& dims)
    : full_(std::uint8_t(frames_to_open)), dims_(dims) {
    if (frames_to_open == 0 || frames_to_open > max_frames_to_open)
        throw std::invalid_argument("cell openings: expected 1.." + std::to_string(max_frames_to_open) +
                                    " frames to open, found " + std::to_string(frames_to_open));
}

void CellOpenings::next(const std::vector<std::uint8_t>& selected, std::vector<std::uint8_t>& drawn) {
    if (selected.size() != dims_.cell_count())
        throw std::invalid_argument("cell openings: " + std::to_string(selected.size()) + " flags, expected " +
                                    std::to_string(dims_.cell_count()));
    drawn.assign(selected.size(), 0);
    openings_.clear();
    if (level_.size() != selected.size()) {
        // The first frame: every selected cell open, and selected in the frames "before" it.
        level_.resize(selected.size());
        history_.resize(selected.size());
        for (std::size_t c = 0; c < selected.size(); ++c) {
            level_[c] = selected[c] ? full_ : 0;
            history_[c] = selected[c] ? 0xff : 0;
        }
    }
    const unsigned lag_bit = 1u << (full_ - 1);
    for (std::size_t c = 0; c < selected.size(); ++c) {
        history_[c] = std::uint8_t((history_[c] << 1) | (selected[c] ? 1u : 0u));
        // Drawn: selected frames_to_open - 1 frames ago, with its cut open; a drawn cell keeps its
        // cut whatever the selection says now (it left: the cut closes once it is no longer drawn).
        const bool lagged = (history_[c] & lag_bit) != 0;
        std::uint8_t& level = level_[c];
        if (!(lagged && level == full_)) {
            if (selected[c] && level < full_) ++level;
            else if (!selected[c] && level > 0) --level;
        }
        if (lagged && level == full_) drawn[c] = 1;
        else if (level > 0) openings_.push_back({std::uint32_t(c), float(double(level) / double(full_))});
    }
    // Beside the cut: a face neighbour is drawn as a primary (its cut is open around the cell).
    const auto drawn_at = [&](int i, int j, int k) {
        return i >= 0 && j >= 0 && k >= 0 && i < dims_.nx && j < dims_.ny && k < dims_.nz &&
               drawn[std::size_t(i) + std::size_t(dims_.nx) * (std::size_t(j) + std::size_t(dims_.ny) * std::size_t(k))];
    };
    for (OpeningCell& opening : openings_) {
        const grid::CellIjk c = grid::cell_ijk(dims_, opening.cell);
        opening.beside_cut = drawn_at(c.i - 1, c.j, c.k) || drawn_at(c.i + 1, c.j, c.k) || drawn_at(c.i, c.j - 1, c.k) ||
                             drawn_at(c.i, c.j + 1, c.k) || drawn_at(c.i, c.j, c.k - 1) || drawn_at(c.i, c.j, c.k + 1);
        opening.opening = depth_share(opening.opening, opening.beside_cut);
    }
}

}  // namespace cutaway::temporal

#include "cutaway/temporal/cell_openings.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace cutaway::temporal {

std::size_t frames_to_open(std::size_t frames_per_step) {
    return std::min(2 * frames_per_step, CellOpenings::max_frames_to_open);
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

void CellOpenings::next(const std::vector<const std::vector<std::uint8_t>*>& window) {
    if (window.empty() || window.size() > full_)
        throw std::invalid_argument("cell openings: a window of " + std::to_string(window.size()) + " frames, expected 1.." +
                                    std::to_string(int(full_)));
    for (const std::vector<std::uint8_t>* flags : window)
        if (flags->size() != dims_.cell_count())
            throw std::invalid_argument("cell openings: " + std::to_string(flags->size()) + " flags, expected " +
                                        std::to_string(dims_.cell_count()));
    const std::vector<std::uint8_t>& drawn = *window.front();
    openings_.clear();
    if (level_.size() != drawn.size()) level_.assign(drawn.size(), 0);  // the first frame
    for (std::size_t c = 0; c < drawn.size(); ++c) {
        std::uint8_t& level = level_[c];
        if (drawn[c]) {
            level = full_;
            continue;
        }
        // Frames until the cell is selected (window.size(): not within the window).
        std::size_t ahead = 1;
        while (ahead < window.size() && !(*window[ahead])[c]) ++ahead;
        if (ahead < window.size()) level = std::max(level, std::uint8_t(full_ - ahead));
        else if (level > 0) --level;
        if (level > 0) openings_.push_back({std::uint32_t(c), float(double(level) / double(full_))});
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

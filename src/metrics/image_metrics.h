#pragma once
// Image metrics of cutaway frames, from per-pixel cell ids and flags (no GL here).
#include <cstdint>
#include <vector>

#include "common/shared_constants.h"

namespace cutaway::metrics {

/// Per-pixel ids of one frame: cell[i] = compact cell + 1 (0 = background), flags[i] as in
/// shaders/common/shared_constants.h. Row order does not matter as long as images agree.
struct PixelIds {
    int width = 0;
    int height = 0;
    const std::vector<std::uint32_t>& cell;
    const std::vector<std::uint32_t>& flags;
};

using shared::flag_border, shared::flag_cut_fill, shared::flag_primary;

struct Exposure {
    double fraction = 1;            ///< visible unchanged / primary pixels (1 when there are none)
    std::size_t primary_pixels = 0; ///< pixels covered by a primary in the primaries-only frame
    std::size_t visible = 0;        ///< of those, pixels showing the same primary cell in the cutaway
};

/// primary_exposure: fraction of the primaries-only image's primary pixels that show the same
/// cell, as a primary, in the cutaway image.
Exposure primary_exposure(const PixelIds& primaries_only, const PixelIds& cutaway);

/// Pixels showing the context's original surface: a secondary face seen from outside its cell
/// (not cut fill, not a border line).
std::size_t context_pixels(const PixelIds& frame);

/// Pixels showing any cell (primary, secondary, cut fill or border).
std::size_t model_pixels(const PixelIds& frame);

struct ContextShare {
    double fraction = 0;           ///< context / model (0 when the frame shows no cell)
    std::size_t context = 0;       ///< context_pixels
    std::size_t model = 0;         ///< model_pixels
};

/// context_share: the share of the model's pixels that show the context's own surface (secondary
/// cells as the model has them). Needs no second frame, so an animation measures it every frame.
ContextShare context_share(const PixelIds& frame);

struct ContextKept {
    double fraction = 1;         ///< (kept - kept_180) / (uncut - kept_180), clamped to [0, 1]
    std::size_t kept = 0;        ///< context pixels of the cutaway frame
    std::size_t kept_180 = 0;    ///< context pixels of the 180-degree-aperture frame
    std::size_t uncut = 0;       ///< context pixels of the frame without a cut
};

/// context_kept: where the cutaway lies between removing nothing (1) and the 180-degree
/// aperture, which removes everything in front of the primaries (0).
ContextKept context_kept(std::size_t kept, std::size_t kept_180, std::size_t uncut);

struct LineWidth {
    double mean = 0;        ///< pixels
    double stddev = 0;      ///< pixels
    std::size_t pixels = 0; ///< border pixels measured
};

/// Width of border lines: for each pixel flagged `mask`, the shortest run of flagged pixels
/// through it along the 4 directions (horizontal, vertical, both diagonals, diagonal runs
/// scaled by sqrt 2). For a straight line of width w at any angle this lies within 8% of w
/// (cos 22.5 degrees), so the spread across pixels measures how erratic the thickness is.
LineWidth line_width(const PixelIds& frame, std::uint32_t mask);

}  // namespace cutaway::metrics

#pragma once
// Metrics of an animation, frame against previous frame (issue 44): cells popping in and out of
// the primary set, and pixels flipping between cut away and kept. No OpenGL here.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace cutaway::metrics {

struct PopCounts {
    std::size_t in = 0;   ///< cells primary now and not before (pop_in)
    std::size_t out = 0;  ///< cells primary before and not now (pop_out)
};

/// Compares two frames' primary flags (one per cell, nonzero = primary). Throws
/// std::invalid_argument when the sizes differ.
PopCounts count_pops(const std::vector<std::uint8_t>& before, const std::vector<std::uint8_t>& after);

/// The paper's open problem is cells that "arbitrary pop in and out" of the primary set: over an
/// animation, a reversal is a cell leaving the set after it entered in an earlier frame, or
/// entering after it left. A front that only advances has none; a value hovering at a range
/// limit makes one at each crossing after its first.
class PopReversals {
public:
    explicit PopReversals(std::size_t cells) : last_change_(cells, 0) {}

    /// The reversals from `before` to `after` (one flag per cell, nonzero = primary), each cell's
    /// change recorded for the frames after. Throws std::invalid_argument when a size differs
    /// from the cell count.
    std::size_t count(const std::vector<std::uint8_t>& before, const std::vector<std::uint8_t>& after);

private:
    std::vector<std::int8_t> last_change_;  ///< per cell: +1 entered, -1 left, 0 not changed yet
};

/// What a pixel shows, for the flicker metric.
enum class CutState : std::uint8_t {
    background = 0,  ///< no cell
    kept = 1,        ///< a cell's surface as the model has it (primary, or a secondary face not cut)
    cut_away = 2,    ///< a cell's inside where the cut surface passes through it (flag_cut_fill)
};

/// Per pixel of a frame, from its ids (image_metrics.h PixelIds: cell + 1 or 0, flags): "cut away"
/// is exactly the cut fill, the pixels where the cut removed the part of a cell in front of the
/// eye. Reading the ids back is all it needs. A face behind the cut seen through a void (inactive
/// cells, outside the model) is counted as kept.
std::vector<CutState> cut_states(const std::vector<std::uint32_t>& cell, const std::vector<std::uint32_t>& flags);

struct CutFlicker {
    double fraction = 0;             ///< changed / model_pixels (0 when there are none)
    std::size_t model_pixels = 0;    ///< pixels showing a cell in either frame
    std::size_t changed = 0;         ///< of those, pixels whose CutState differs
};

/// cut_flicker: the share of model pixels whose state (background, kept, cut away) changed
/// between two frames of the same size. Throws std::invalid_argument when the sizes differ.
CutFlicker cut_flicker(const std::vector<CutState>& before, const std::vector<CutState>& after);

}  // namespace cutaway::metrics

#pragma once
// Smooth coherence's cut, cell by cell: a cell that enters the primaries opens its own cut before
// it is drawn as a primary, and a cell that leaves closes it after, each over a few frames.
// A primary's cut is a frustum from the camera to its rear; a cell entering where nothing was cut
// flips every pixel of that frustum's cross-section from kept to cut away in one frame, the
// largest flicker an animation has where single cells enter (SPE9's water). Here the cut of an
// entering cell reaches deeper frame by frame, from the model's nearest depth (cutting nothing)
// to the cell's rear (CutawayRenderer::set_opening_cells draws it, FramePass::opening_cut), and
// the cell is drawn as a primary once the cut has reached it, so every primary pixel of a frame
// stays visible. Exits mirror entries: the cell is drawn as long after it leaves the selection
// as entries are late, then its cut closes. So the drawn primaries are the selection of
// frames_to_open - 1 frames before, the order and pacing of the changes kept. No OpenGL here.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "grid/grid_dims.h"

namespace cutaway::temporal {

/// A cell whose cut is partly open: `opening` in (0, 1) is the share of the depth from the
/// model's nearest depth to the cell's rear that its cut reaches.
struct OpeningCell {
    std::uint32_t cell = 0;  ///< Eclipse index
    float opening = 0;
    /// A face neighbour is drawn as a primary: the cut is open around the cell already, and its
    /// own cut opens from the depth of their walls over its footprint, not from the model's top
    /// (CutawayRenderer::set_opening_cells).
    bool beside_cut = false;
};

class CellOpenings {
public:
    /// The most frames a cut takes to open (the history kept per cell is one byte).
    static constexpr std::size_t max_frames_to_open = 8;

    /// `frames_to_open`: frames over which a cell's cut opens, the last of them the first the cell
    /// is drawn (1 .. max_frames_to_open; 1: cells enter and leave at once, as without openings).
    /// Throws std::invalid_argument otherwise.
    /// `dims`: the grid's, for the cells' neighbours.
    CellOpenings(std::size_t frames_to_open, const grid::GridDims& dims);

    /// The next frame: `selected` are the frame's primary flags as coherence selects them (one per
    /// Eclipse cell); `drawn` receives the flags of the cells drawn as primaries: those selected
    /// frames_to_open - 1 frames before whose cut is open. A cell's cut level moves one step per
    /// frame towards full while it is selected or drawn, towards 0 otherwise; between the two its
    /// cut is opening by sqrt(level / full), as a cut's cross-section grows with the square of its
    /// depth behind the surface: about equal areas flip per frame. The first frame finds every
    /// selected cell drawn (nothing was shown before it to flicker against).
    void next(const std::vector<std::uint8_t>& selected, std::vector<std::uint8_t>& drawn);

    /// The cells opening or closing in the last frame, by Eclipse index.
    const std::vector<OpeningCell>& openings() const { return openings_; }

private:
    std::uint8_t full_;
    grid::GridDims dims_;
    std::vector<std::uint8_t> level_;    ///< per Eclipse cell, 0..full_
    std::vector<std::uint8_t> history_;  ///< per Eclipse cell, bit k: selected k frames before (k < 8)
    std::vector<OpeningCell> openings_;
};

}  // namespace cutaway::temporal

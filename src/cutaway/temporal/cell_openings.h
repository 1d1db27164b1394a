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

/// Frames over which smooth coherence opens a cell's cut: a report step's frames and one more, at
/// most CellOpenings::max_frames_to_open; a cell is drawn that many frames less one after it
/// enters. Longer openings flicker less and lag more: on zaphirus's waterflood at 4 frames per
/// step (960x540), opening over 4, 5, 6 and 8 frames lowered the largest flicker 2.5, 3.1, 3.6
/// and 4.0 times against none's and raised the context share at report steps by 6, 10, 15 and
/// 22% (fewer primaries drawn yet); 5 is where both targets of issue 44 hold.
std::size_t frames_to_open(std::size_t frames_per_step);

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
    /// cut is opening by depth_share(level / full). The first frame finds every selected cell
    /// drawn (nothing was shown before it to flicker against).
    void next(const std::vector<std::uint8_t>& selected, std::vector<std::uint8_t>& drawn);

    /// The cells opening or closing in the last frame, by Eclipse index.
    const std::vector<OpeningCell>& openings() const { return openings_; }

    /// The share of its depth a cell's cut reaches after `frames_share` of its frames to open.
    /// Alone, from where its view rays enter the model: the share to the power 5/4 (on zaphirus's
    /// first primaries what a cut uncovers grows faster than its depth early on: the powers 1/2,
    /// 1, 5/4 and 3/2 left a largest frame's flicker of 0.45, 0.27, 0.22 and 0.24). Beside the
    /// cut, from its neighbours' wall drop: the power 3/8 (a wall seen edge-on sweeps a band of
    /// the screen late in the opening; on SPE9's water the powers 1/4, 1/2 and 1 left 0.39, 0.32
    /// and 0.50 of a cell's flips in the largest frame, 3/8 left 0.28). Both are empirical
    /// choices on those cases.
    static float depth_share(float frames_share, bool beside_cut);

private:
    std::uint8_t full_;
    grid::GridDims dims_;
    std::vector<std::uint8_t> level_;    ///< per Eclipse cell, 0..full_
    std::vector<std::uint8_t> history_;  ///< per Eclipse cell, bit k: selected k frames before (k < 8)
    std::vector<OpeningCell> openings_;
};

}  // namespace cutaway::temporal

#pragma once
// Smooth coherence's cut, cell by cell: a cell that enters the primaries opens its own cut in the
// frames before it is drawn as a primary, and a cell that leaves closes it in the frames after,
// each over a few frames.
// A primary's cut is a frustum from the camera to its rear; a cell entering where nothing was cut
// flips every pixel of that frustum's cross-section from kept to cut away in one frame, the
// largest flicker an animation has where single cells enter (SPE9's water). Here the cut of an
// entering cell reaches deeper frame by frame, from the model's nearest depth (cutting nothing)
// to the cell's rear (CutawayRenderer::set_opening_cells draws it, FramePass::opening_cut), and
// is open when the cell enters, so every primary pixel of a frame stays visible. The openings
// read the selection of the frames ahead (CoherentSequence keeps them), so the drawn primaries
// are the frame's selection itself: no lag behind the values shown. No OpenGL here.
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

/// Frames over which smooth coherence opens a cell's cut: two report steps' frames, at most
/// CellOpenings::max_frames_to_open; the last of them is the first the cell is drawn. Longer
/// openings flicker less (results/front_tracking measures the flicker against none's): at 4 frames
/// a step, SPE9's gas front (a single cell entering) flickered 0.0515 in a frame over 5 frames and
/// 0.0445 over 8, against none's 0.149 (2.9x and 3.3x).
std::size_t frames_to_open(std::size_t frames_per_step);

class CellOpenings {
public:
    /// The most frames a cut takes to open (CoherentSequence keeps as many frames ahead).
    static constexpr std::size_t max_frames_to_open = 8;

    /// `frames_to_open`: frames over which a cell's cut opens, the last of them the first the cell
    /// is drawn (1 .. max_frames_to_open; 1: cells enter and leave at once, as without openings).
    /// Throws std::invalid_argument otherwise.
    /// `dims`: the grid's, for the cells' neighbours.
    CellOpenings(std::size_t frames_to_open, const grid::GridDims& dims);

    /// The next frame. `window[k]` holds the primary flags (one per Eclipse cell) k frames on:
    /// window[0] the frame's own selection, drawn as it is; then up to frames_to_open - 1 frames
    /// ahead (fewer at an animation's end). A cell selected d frames on opens its cut to at least
    /// (frames_to_open - d) / frames_to_open of its frames; a cell selected nowhere in the window
    /// closes its cut one frame's share per frame. Between the two its cut is opening by
    /// depth_share. The first frame finds the cuts of the frame's selection open (nothing was
    /// shown before it to flicker against).
    void next(const std::vector<const std::vector<std::uint8_t>*>& window);

    /// The cells opening or closing in the last frame, by Eclipse index (never one of its
    /// selection).
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
    std::vector<std::uint8_t> level_;  ///< per Eclipse cell, 0..full_: frames of its cut open
    std::vector<OpeningCell> openings_;
};

}  // namespace cutaway::temporal

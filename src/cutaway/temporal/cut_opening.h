#pragma once
// How far the cut is open in a frame of a smooth animation. Primaries appearing where there were
// none open a whole cone at once: every pixel in front of them flips from kept to cut away in one
// frame, the largest flicker an animation has. Smooth coherence opens the cut at a bounded speed
// instead: from half the aperture on the primaries' first frame to the full one, over a number of
// frames. Not from nothing: a narrow cut's upright walls, mean-filtered, cover the primaries'
// edges (primary exposure falls below 1 under about a third of the default 60 degrees), and every
// primary pixel must stay visible in every frame. No OpenGL here.
#include <cstddef>

namespace cutaway::temporal {

class CutOpening {
public:
    /// `frames_to_open`: frames from the primaries' first frame to the full aperture (>= 1).
    /// Throws std::invalid_argument for 0.
    explicit CutOpening(std::size_t frames_to_open);

    /// The next frame's opening in [0, 1] (opened_aperture_deg's `opening`) from its primary
    /// count: 0 on the frame the first primaries appear, growing by 1 / frames_to_open per frame
    /// while there are primaries, up to 1; 0 on a frame without primaries (there is no cut, and
    /// the next primaries open it again). Primaries in the very first frame find the cut open:
    /// nothing was shown before it, so there is nothing to flicker against.
    float next(std::size_t primary_cells);

private:
    std::size_t frames_to_open_;
    std::size_t frames_open_ = 0;  ///< frames with primaries in a row, this one included (0: none now)
    bool first_frame_ = true;
};

/// The full opening angle (degrees) of a cut `opening` of the way (0..1) from half of `full_deg`
/// to `full_deg`. The cut's cross-section grows with the square of tan(angle / 2), so that square
/// is interpolated: each step of the opening uncovers about as much area, and the flicker is
/// spread evenly over the frames. A full 180 degrees (flat walls, tan infinite) is interpolated
/// in angle instead.
float opened_aperture_deg(float full_deg, float opening);

}  // namespace cutaway::temporal

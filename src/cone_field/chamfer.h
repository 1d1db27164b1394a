#pragma once
// Cone-field cut by chamfer propagation (Borgefors 1986): two raster passes with a 3x3 or 5x5
// mask. Runs on the CPU: each pixel of a pass reads values the same pass has just written (the
// raster order is a sequential dependency), which does not map onto a fragment shader.
//
// Every pixel starts at max(0, seed depth) and takes d(p) = max(d(p), d(n) - m * w(n -> p)) over
// the mask's neighbours n already visited: top-to-bottom, left-to-right with the forward half of
// the mask, then the reverse order with the backward half. Two passes give the exact max over
// seeds of z(q) - m * chamfer_length(q -> p), where chamfer_length is the shortest path of mask
// steps; the error against the Euclidean cone is the mask's length error, two-sided except for
// (1, sqrt2), which only overestimates lengths (the cut is never above exact).
#include <string_view>
#include <vector>

#include "cone_field/cone_image.h"

namespace cutaway::cone_field {

enum class ChamferMask {
    city_diagonal_3x3,  ///< 3x3, steps 1 and sqrt(2): lengths 0 .. +8.24% too long
    borgefors_3x3,      ///< 3x3 <3,4> / 3: steps 1 and 4/3, lengths -5.72% .. +5.41%
    borgefors_5x5,      ///< 5x5 <5,7,11> / 5: steps 1, 1.4 and 2.2 (knight), lengths -1.61% .. +1.98%
    /// 3x3, steps 1 and 1: the chessboard (L-infinity) length max(|dx|, |dy|), exactly. Not a
    /// Euclidean approximation: its "cones" are square pyramids, the frustums of boxes with equal
    /// wall slopes (the frustum-sweep strategy).
    chessboard_3x3,
};

/// "chamfer_3x3_1_sqrt2", "chamfer_3x3_3_4", "chamfer_5x5_5_7_11", "chessboard_3x3_1_1".
std::string_view chamfer_mask_name(ChamferMask mask);

/// One step of a mask: offset (dx, dy) from the neighbour n to the pixel p, and its length, pixels.
struct ChamferStep {
    int dx = 0;
    int dy = 0;
    double length = 0.0;
};

/// The forward half of the mask: steps whose neighbour n = p - (dx, dy) comes before p in
/// top-to-bottom, left-to-right order. The backward half is the same steps negated.
std::vector<ChamferStep> chamfer_forward_steps(ChamferMask mask);

/// The cut surface by two chamfer passes; m = slope_per_pixel (depth units per pixel). Output:
/// the seed image's size, depth units, 0 where no cone reaches. Throws std::invalid_argument for
/// a malformed seed image or a slope that is not positive.
FloatImage chamfer_cut(const SeedImage& seeds, double slope_per_pixel, ChamferMask mask);

}  // namespace cutaway::cone_field

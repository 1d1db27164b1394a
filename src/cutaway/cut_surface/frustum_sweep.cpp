// The frustum union computed in O(pixels) instead of O(primaries x wall area): with the default
// box seeds (each primary's back face widened by a pixel) and chessboard sweeps on the GPU
// (gpu_chamfer.cpp), the cut is max over seed pixels q of z(q) - m max(|dx|, |dy|): the union of
// square frustums whose walls all fall m per pixel, a max-plus dilation of the back-face image by
// an L-infinity pyramid, which the sweeps compute exactly.
//
// Where it equals the rasterised union: when every wall of every frustum has the same pixel slope
// m (frustum.geom's CONSTANT_WALL_SLOPE), it lies at most m below it (the seeds are the back
// faces' pixel centres, the raster walls start at the faces' exact edges) and never above, down to
// the rim (tests/gl/frustum_sweep_gl_test.cpp). The paper's walls are not like that: their slope in
// pixels grows with each box's back depth and, at a fixed angle, with its distance from the image
// centre; m here is the cone slope at the primaries' centroid (cone_field_strategy.h), so the two
// agree for primaries near that depth and the centre. The sweep also does not stop at the rim
// (nothing lies in front of it, so that changes no pixel of the frame), and it ignores the
// vertical aperture (square pyramids).
#include "cutaway/cut_surface/cone_field_strategy.h"

namespace cutaway::pipeline {

CutSurfaceEntry frustum_sweep_entry() { return chamfer_entry("frustum-sweep", cone_field::ChamferMask::chessboard_3x3); }

}  // namespace cutaway::pipeline

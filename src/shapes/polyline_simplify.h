#pragma once
// A polyline with the points dropped that lie within a tolerance of the simplified line
// (Douglas-Peucker): a well's path through stacked cells' centres is nearly straight, and a tube
// around it needs a ring only where the path bends.
#include <vector>

#include "grid/point3.h"

namespace cutaway::shapes {

/// `path` keeping its first and last points and every point farther than `tolerance` from the
/// segment between the points kept around it; every dropped point lies within `tolerance` of
/// the result. Paths of fewer than three points are returned as they are.
std::vector<grid::Point3> simplify_polyline(const std::vector<grid::Point3>& path, double tolerance);

}  // namespace cutaway::shapes

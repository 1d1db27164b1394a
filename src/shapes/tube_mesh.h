#pragma once
// A tube of circular cross-section around a polyline, closed at both ends: a well's path drawn as a
// solid, a `cylinder:` cut volume (a path of two points), a `well:NAME,R` cut volume.
#include <vector>

#include "grid/point3.h"
#include "shapes/triangle_mesh.h"

namespace cutaway::shapes {

/// Sides of the drawn well tubes and of the cut volumes' tubes (cylinder:, well:): round at the
/// few tens of pixels a tube spans, and the cut around a well follows its drawn tube. Inscribed
/// in the circle, the polygon lies within R (1 - cos(pi / sides)) = 1.9% of R inside it.
inline constexpr int tube_sides = 16;

/// The tube of `radius` around `path` (consecutive equal points are skipped), its cross-section a
/// regular polygon of `sides` sides (at least 3). At each inner point the ring lies in the plane
/// that bisects the two segments' directions, so the tube's wall is continuous around bends; the
/// ring's orientation follows the path by parallel transport (no twist). Both ends closed by flat
/// caps. Throws std::invalid_argument for a path of fewer than two distinct points, a radius that
/// is not finite and positive, or fewer than 3 sides.
TriangleMesh tube_mesh(const std::vector<grid::Point3>& path, double radius, int sides = tube_sides);

}  // namespace cutaway::shapes

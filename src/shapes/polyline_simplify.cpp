#include "shapes/polyline_simplify.h"

#include <cmath>
#include <cstddef>

namespace cutaway::shapes {
namespace {

/// Distance from `p` to the segment a-b.
double distance_to_segment(const grid::Point3& p, const grid::Point3& a, const grid::Point3& b) {
    const double dx = b.x - a.x, dy = b.y - a.y, dz = b.z - a.z;
    const double length2 = dx * dx + dy * dy + dz * dz;
    double t = length2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy + (p.z - a.z) * dz) / length2 : 0;
    t = std::fmax(0.0, std::fmin(1.0, t));
    const double ex = a.x + t * dx - p.x, ey = a.y + t * dy - p.y, ez = a.z + t * dz - p.z;
    return std::sqrt(ex * ex + ey * ey + ez * ez);
}

/// Marks the points of (first, last) to keep.
void keep_between(const std::vector<grid::Point3>& path, std::size_t first, std::size_t last, double tolerance,
                  std::vector<bool>& keep) {
    if (last <= first + 1) return;
    std::size_t farthest = first;
    double distance = -1;
    for (std::size_t i = first + 1; i < last; ++i) {
        const double d = distance_to_segment(path[i], path[first], path[last]);
        if (d > distance) {
            distance = d;
            farthest = i;
        }
    }
    if (distance <= tolerance) return;
    keep[farthest] = true;
    keep_between(path, first, farthest, tolerance, keep);
    keep_between(path, farthest, last, tolerance, keep);
}

}  // namespace

std::vector<grid::Point3> simplify_polyline(const std::vector<grid::Point3>& path, double tolerance) {
    if (path.size() < 3) return path;
    std::vector<bool> keep(path.size(), false);
    keep.front() = keep.back() = true;
    keep_between(path, 0, path.size() - 1, tolerance, keep);
    std::vector<grid::Point3> kept;
    for (std::size_t i = 0; i < path.size(); ++i)
        if (keep[i]) kept.push_back(path[i]);
    return kept;
}

}  // namespace cutaway::shapes

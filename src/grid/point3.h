#pragma once
// Plain 3D points and boxes in model units (x east, y north, z depth, positive down).
#include <algorithm>
#include <limits>

namespace cutaway::grid {

struct Point3 {
    double x = 0;
    double y = 0;
    double z = 0;
};

struct Box3 {
    Point3 min{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
               std::numeric_limits<double>::infinity()};
    Point3 max{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
               -std::numeric_limits<double>::infinity()};

    bool empty() const { return min.x > max.x; }
    void extend(const Point3& p) {
        min = {std::min(min.x, p.x), std::min(min.y, p.y), std::min(min.z, p.z)};
        max = {std::max(max.x, p.x), std::max(max.y, p.y), std::max(max.z, p.z)};
    }
    void extend(const Box3& b) {
        if (!b.empty()) {
            extend(b.min);
            extend(b.max);
        }
    }
};

}  // namespace cutaway::grid

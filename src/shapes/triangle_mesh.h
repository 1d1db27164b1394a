#pragma once
// A closed triangle mesh in the model's coordinates: what a cut volume or a well tube is made of.
#include <array>
#include <cstdint>
#include <vector>

#include "grid/point3.h"

namespace cutaway::shapes {

struct TriangleMesh {
    std::vector<grid::Point3> positions;
    std::vector<grid::Point3> normals;  ///< one per position, unit length, pointing out of the solid
    std::vector<std::array<std::uint32_t, 3>> triangles;  ///< (b - a) x (c - a) points out of the solid
};

/// The mesh's axis-aligned bounds (empty for a mesh without positions).
grid::Box3 bounds(const TriangleMesh& mesh);

/// `b` appended to `a` (indices of b shifted past a's positions).
void append(TriangleMesh& a, const TriangleMesh& b);

}  // namespace cutaway::shapes

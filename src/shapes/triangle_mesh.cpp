#include "shapes/triangle_mesh.h"

namespace cutaway::shapes {

grid::Box3 bounds(const TriangleMesh& mesh) {
    grid::Box3 box;
    for (const grid::Point3& p : mesh.positions) box.extend(p);
    return box;
}

void append(TriangleMesh& a, const TriangleMesh& b) {
    const auto offset = static_cast<std::uint32_t>(a.positions.size());
    a.positions.insert(a.positions.end(), b.positions.begin(), b.positions.end());
    a.normals.insert(a.normals.end(), b.normals.begin(), b.normals.end());
    for (const auto& t : b.triangles) a.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
}

}  // namespace cutaway::shapes

#pragma once
// Each triangle with the vertex across each of its edges (OpenGL's GL_TRIANGLES_ADJACENCY order),
// so a geometry shader can tell a silhouette edge (its neighbour faces the other way) from an
// inner one. Positions equal to 1e-9 of the mesh's extent are one vertex: meshes repeat positions
// across rings and caps.
#include <array>
#include <cstdint>
#include <vector>

#include "shapes/triangle_mesh.h"

namespace cutaway::shapes {

/// Six position indices per triangle: a, across(a b), b, across(b c), c, across(c a), where
/// across(x y) is the third vertex of the triangle on the other side of edge x y. An edge no
/// other triangle shares (an open mesh) gets the triangle's own third vertex, which makes the
/// "neighbour" the triangle itself turned over: the edge then reads as a silhouette.
std::vector<std::array<std::uint32_t, 6>> triangle_adjacency(const TriangleMesh& mesh);

}  // namespace cutaway::shapes

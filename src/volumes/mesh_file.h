#pragma once
// `mesh:FILE` cut volumes: a closed triangle mesh from a PLY or OBJ file, read with CGAL's IO
// (the one translation unit of src/ that includes CGAL, as generators/ keeps its own).
#include <cstddef>
#include <string>

#include "shapes/triangle_mesh.h"

namespace cutaway::volumes {

/// Bytes of memory reading a mesh file may take per byte of the file: a binary PLY stores a
/// triangle in 13 bytes and a vertex in 12, while the polygon soup, CGAL's Surface_mesh (three
/// halfedge pairs per face, connectivity and property maps) and the TriangleMesh built from it
/// hold about 400 bytes per triangle at once. Text files (OBJ, ASCII PLY) need less per byte.
inline constexpr std::size_t mesh_bytes_per_file_byte = 32;

/// The mesh in FILE (.ply or .obj, any case), faces triangulated, wound outward, with vertex
/// normals. Throws std::invalid_argument with a one-line message (no prefix) for a missing or
/// unreadable file, another extension, a file whose size times mesh_bytes_per_file_byte exceeds
/// `memory_limit_bytes` (checked before reading), no faces, a non-manifold or non-orientable
/// surface, or an open one (a boundary edge).
shapes::TriangleMesh read_closed_mesh(const std::string& file, std::size_t memory_limit_bytes);

}  // namespace cutaway::volumes

#include "volumes/mesh_file.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include "io/input_file.h"

namespace cutaway::volumes {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;

std::string lower_extension(const std::string& file) {
    std::string ext = std::filesystem::path(file).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

void check_file(const std::string& file, std::size_t memory_limit_bytes) {
    const std::string ext = lower_extension(file);
    if (ext != ".ply" && ext != ".obj") throw std::invalid_argument(file + ": expected a .ply or .obj file, found '" + ext + "'");
    if (const std::string problem = io::input_file_problem(file); !problem.empty())
        throw std::invalid_argument(file + ": expected a readable mesh file, found " + problem);
    const std::uintmax_t bytes = std::filesystem::file_size(file);
    if (bytes > memory_limit_bytes / mesh_bytes_per_file_byte)
        throw std::invalid_argument(file + ": " + std::to_string(bytes) + " bytes need about " +
                                    std::to_string(bytes * mesh_bytes_per_file_byte / (1u << 20)) +
                                    " MiB to read, more than --memory-limit-gb leaves (" +
                                    std::to_string(memory_limit_bytes / (1u << 20)) + " MiB)");
}

/// The soup as a Surface_mesh, refused unless it is a closed, manifold, orientable surface.
Mesh closed_mesh(const std::string& file, std::vector<Point>& points, std::vector<std::vector<std::size_t>>& polygons) {
    if (polygons.empty()) throw std::invalid_argument(file + ": expected a closed triangle mesh, found no faces");
    for (const auto& polygon : polygons) {
        if (polygon.size() < 3) throw std::invalid_argument(file + ": expected faces of 3 or more vertices");
        for (std::size_t index : polygon)
            if (index >= points.size()) throw std::invalid_argument(file + ": a face names a vertex the file does not have");
    }
    // Exporters that write each face's corners anew (as STL does) describe a closed surface
    // whose faces share no vertex index: coincident points are one vertex.
    PMP::merge_duplicate_points_in_polygon_soup(points, polygons);
    // A soup whose edges are shared by at most two consistently orientable faces, without
    // non-manifold vertices, is a polygon mesh; anything else (three faces on an edge, two
    // surfaces touching at a vertex, a Moebius band) cannot bound a volume.
    if (!PMP::is_polygon_soup_a_polygon_mesh(polygons))
        throw std::invalid_argument(file + ": expected a manifold, orientable surface, found non-manifold edges or "
                                           "vertices (or faces that cannot be oriented consistently)");
    Mesh mesh;
    PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
    points = {};
    polygons = {};
    if (!CGAL::is_valid_polygon_mesh(mesh)) throw std::invalid_argument(file + ": expected a valid polygon mesh");
    if (!CGAL::is_closed(mesh))
        throw std::invalid_argument(file + ": expected a closed mesh, found boundary edges (an open surface)");
    return mesh;
}

shapes::TriangleMesh triangle_mesh(Mesh& mesh) {
    PMP::triangulate_faces(mesh);
    if (!PMP::is_outward_oriented(mesh)) PMP::reverse_face_orientations(mesh);
    auto normals = mesh.add_property_map<Mesh::Vertex_index, Kernel::Vector_3>("v:normal", CGAL::NULL_VECTOR).first;
    PMP::compute_vertex_normals(mesh, normals);
    shapes::TriangleMesh out;
    // Surface_mesh indices are dense after reading (nothing removed).
    for (Mesh::Vertex_index v : mesh.vertices()) {
        const Point& p = mesh.point(v);
        const Kernel::Vector_3& n = normals[v];
        out.positions.push_back({p.x(), p.y(), p.z()});
        out.normals.push_back({n.x(), n.y(), n.z()});
    }
    for (Mesh::Face_index f : mesh.faces()) {
        std::array<std::uint32_t, 3> triangle{};
        std::size_t corner = 0;
        for (Mesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) triangle[corner++] = std::uint32_t(v);
        out.triangles.push_back(triangle);
    }
    return out;
}

}  // namespace

shapes::TriangleMesh read_closed_mesh(const std::string& file, std::size_t memory_limit_bytes) {
    check_file(file, memory_limit_bytes);
    std::vector<Point> points;
    std::vector<std::vector<std::size_t>> polygons;
    if (!CGAL::IO::read_polygon_soup(file, points, polygons))
        throw std::invalid_argument(file + ": expected a PLY or OBJ polygon mesh, found content CGAL cannot read");
    Mesh mesh = closed_mesh(file, points, polygons);
    return triangle_mesh(mesh);
}

}  // namespace cutaway::volumes

#include "volumes/volume_mesh.h"

#include <algorithm>
#include <stdexcept>

#include "shapes/polyline_simplify.h"
#include "shapes/tube_mesh.h"
#include "volumes/mesh_file.h"

namespace cutaway::volumes {
namespace {

std::string well_names(const WellPaths* wells) {
    if (!wells || wells->empty()) return "the model has no wells";
    std::string names;
    for (const auto& [name, path] : *wells) names += (names.empty() ? "" : ", ") + name;
    return "the model's wells: " + names;
}

double coordinate(const grid::Point3& p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }

struct Build {
    const VolumeBuildContext& context;

    shapes::TriangleMesh operator()(const BoxVolume& b) const { return box_mesh(b.min, b.max); }
    shapes::TriangleMesh operator()(const CylinderVolume& c) const {
        return shapes::tube_mesh({c.from, c.to}, c.radius, tube_sides);
    }
    shapes::TriangleMesh operator()(const WellVolume& w) const {
        if (!context.wells || !context.wells->count(w.name))
            throw std::invalid_argument("unknown well " + w.name + " (" + well_names(context.wells) + ")");
        const double radius = w.radius.value_or(context.default_well_radius);
        try {
            // A ring only where the path bends by more than a twentieth of the radius: stacked cells'
            // centres are nearly in line, and every ring's triangles cost stage 1 time.
            const std::vector<grid::Point3> path = shapes::simplify_polyline(context.wells->at(w.name), 0.05 * radius);
            return shapes::tube_mesh(path, radius, tube_sides);
        } catch (const std::invalid_argument& e) {
            throw std::invalid_argument("well " + w.name + ": " + e.what());
        }
    }
    shapes::TriangleMesh operator()(const MeshVolume& m) const { return read_closed_mesh(m.file, context.memory_limit_bytes); }
};

}  // namespace

double default_well_radius(const grid::Box3& b) {
    return 0.02 * std::max(b.max.x - b.min.x, b.max.y - b.min.y);
}

shapes::TriangleMesh build_volume_mesh(const CutVolume& volume, const VolumeBuildContext& context) {
    try {
        return std::visit(Build{context}, volume);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("--cut-volume '" + spec_text(volume) + "': " + e.what());
    }
}

shapes::TriangleMesh box_mesh(const grid::Point3& lo, const grid::Point3& hi) {
    shapes::TriangleMesh mesh;
    // Each face: its outward axis and sign, and two in-face axes ordered so that (b - a) x (c - a)
    // points out.
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            const std::uint32_t first = std::uint32_t(mesh.positions.size());
            for (int corner = 0; corner < 4; ++corner) {
                const int cu = corner & 1, cv = corner >> 1;
                double p[3], n[3] = {0, 0, 0};
                p[axis] = coordinate(side ? hi : lo, axis);
                p[u] = coordinate(cu ? hi : lo, u);
                p[v] = coordinate(cv ? hi : lo, v);
                n[axis] = side ? 1 : -1;
                mesh.positions.push_back({p[0], p[1], p[2]});
                mesh.normals.push_back({n[0], n[1], n[2]});
            }
            // u x v = +axis: counter-clockwise (0, 1, 3), (0, 3, 2) seen from +axis.
            if (side)
                mesh.triangles.insert(mesh.triangles.end(), {{first, first + 1, first + 3}, {first, first + 3, first + 2}});
            else
                mesh.triangles.insert(mesh.triangles.end(), {{first, first + 3, first + 1}, {first, first + 2, first + 3}});
        }
    return mesh;
}

}  // namespace cutaway::volumes

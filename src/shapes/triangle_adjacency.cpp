#include "shapes/triangle_adjacency.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>
#include <utility>

namespace cutaway::shapes {
namespace {

using PositionKey = std::tuple<long long, long long, long long>;

/// One index per distinct position (the first that holds it), positions rounded to 1e-9 of the
/// mesh's extent: a tube's rings meet at points computed from two frames, equal but for the last
/// bits. Two points either side of a rounding step stay apart: their edge then reads as a
/// silhouette, which only draws a wall more.
std::vector<std::uint32_t> canonical_indices(const TriangleMesh& mesh) {
    const grid::Box3 box = bounds(mesh);
    const double extent = std::max({box.max.x - box.min.x, box.max.y - box.min.y, box.max.z - box.min.z, 1e-300});
    const double step = 1e-9 * extent;
    std::map<PositionKey, std::uint32_t> first;
    std::vector<std::uint32_t> canonical(mesh.positions.size());
    for (std::uint32_t i = 0; i < mesh.positions.size(); ++i) {
        const grid::Point3& p = mesh.positions[i];
        const PositionKey key{std::llround((p.x - box.min.x) / step), std::llround((p.y - box.min.y) / step),
                              std::llround((p.z - box.min.z) / step)};
        canonical[i] = first.try_emplace(key, i).first->second;
    }
    return canonical;
}

}  // namespace

std::vector<std::array<std::uint32_t, 6>> triangle_adjacency(const TriangleMesh& mesh) {
    const std::vector<std::uint32_t> canonical = canonical_indices(mesh);
    // Directed edge (from, to) by canonical index -> the third vertex of the triangle holding it.
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> third;
    for (const auto& t : mesh.triangles)
        for (int e = 0; e < 3; ++e) third[{canonical[t[e]], canonical[t[(e + 1) % 3]]}] = t[(e + 2) % 3];
    std::vector<std::array<std::uint32_t, 6>> adjacency;
    adjacency.reserve(mesh.triangles.size());
    for (const auto& t : mesh.triangles) {
        std::array<std::uint32_t, 6> a{};
        for (int e = 0; e < 3; ++e) {
            // The neighbour holds the edge the other way round.
            const auto across = third.find({canonical[t[(e + 1) % 3]], canonical[t[e]]});
            a[2 * e] = t[e];
            a[2 * e + 1] = across != third.end() ? across->second : t[(e + 2) % 3];
        }
        adjacency.push_back(a);
    }
    return adjacency;
}

}  // namespace cutaway::shapes

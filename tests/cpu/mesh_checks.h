#pragma once
// Invariants of closed triangle meshes (shapes/triangle_mesh.h) shared by the tube and cut-volume tests.
#include <cmath>
#include <map>
#include <tuple>
#include <utility>

#include "shapes/triangle_mesh.h"

namespace cutaway::shapes {

/// Signed volume by the divergence theorem: positive when every triangle is wound outward.
inline double enclosed_volume(const TriangleMesh& mesh) {
    double six_volume = 0;
    for (const auto& t : mesh.triangles) {
        const grid::Point3 &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
        six_volume += a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z - b.z * c.x) + a.z * (b.x * c.y - b.y * c.x);
    }
    return six_volume / 6;
}

/// Edges by position (meshes duplicate positions across rings and caps), rounded to 1e-9.
using Key = std::pair<std::tuple<long long, long long, long long>, std::tuple<long long, long long, long long>>;
inline std::tuple<long long, long long, long long> rounded(const grid::Point3& p) {
    return {std::llround(p.x * 1e9), std::llround(p.y * 1e9), std::llround(p.z * 1e9)};
}

/// Every directed edge appears once and its reverse once: a closed, consistently wound surface.
inline bool closed_and_consistent(const TriangleMesh& mesh) {
    std::map<Key, int> directed;
    for (const auto& t : mesh.triangles)
        for (int e = 0; e < 3; ++e)
            ++directed[{rounded(mesh.positions[t[e]]), rounded(mesh.positions[t[(e + 1) % 3]])}];
    for (const auto& [edge, count] : directed) {
        if (count != 1) return false;
        const auto reverse = directed.find({edge.second, edge.first});
        if (reverse == directed.end() || reverse->second != 1) return false;
    }
    return true;
}

}  // namespace cutaway::shapes

// Tubes around polylines: closed (every edge shared by two triangles in opposite directions),
// wound outward, enclosing the volume of a prism of the polygon cross-section.
#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "shapes/polyline_simplify.h"
#include "shapes/triangle_adjacency.h"
#include "shapes/tube_mesh.h"
#include "mesh_checks.h"

namespace cutaway::shapes {
namespace {

double polygon_area(double radius, int sides) {
    return 0.5 * sides * radius * radius * std::sin(2 * std::acos(-1.0) / sides);
}

TEST(TubeMesh, StraightTubeIsAClosedPrism) {
    const TriangleMesh tube = tube_mesh({{0, 0, 0}, {0, 0, 10}}, 2.0, 12);
    EXPECT_TRUE(closed_and_consistent(tube));
    // 1e-9 relative: only rounding separates the mesh from the exact prism.
    EXPECT_NEAR(enclosed_volume(tube), polygon_area(2.0, 12) * 10, 1e-9 * polygon_area(2.0, 12) * 10);
    const grid::Box3 box = bounds(tube);
    EXPECT_NEAR(box.min.z, 0, 1e-12);
    EXPECT_NEAR(box.max.z, 10, 1e-12);
    EXPECT_NEAR(box.max.x, 2, 1e-12);
}

TEST(TubeMesh, BentPathStaysClosedAndKeepsItsVolume) {
    // A right-angle bend: the mitred joint adds and removes equal wedges, so the volume is the
    // cross-section times the path's length (Pappus for a mitre, exact for polygon sections).
    const TriangleMesh tube = tube_mesh({{0, 0, 0}, {0, 0, 10}, {10, 0, 10}, {10, 5, 10}}, 1.0, 16);
    EXPECT_TRUE(closed_and_consistent(tube));
    EXPECT_NEAR(enclosed_volume(tube), polygon_area(1.0, 16) * 25, 1e-6 * polygon_area(1.0, 16) * 25);
}

TEST(TubeMesh, NormalsPointAwayFromThePath) {
    const TriangleMesh tube = tube_mesh({{1, 2, 3}, {1, 2, 9}}, 0.5, 8);
    for (std::size_t i = 0; i < tube.positions.size(); ++i) {
        const grid::Point3 &p = tube.positions[i], &n = tube.normals[i];
        const double radial = (p.x - 1) * n.x + (p.y - 2) * n.y;  // side walls point out radially
        const double axial = n.z * (p.z < 6 ? -1 : 1);             // caps point out of the ends
        EXPECT_GT(radial + axial, 0) << "vertex " << i;
    }
}

TEST(TubeMesh, RefusesDegenerateInput) {
    EXPECT_THROW(tube_mesh({{0, 0, 0}, {0, 0, 0}}, 1.0), std::invalid_argument);
    EXPECT_THROW(tube_mesh({{0, 0, 0}, {0, 0, 1}}, 0.0), std::invalid_argument);
    EXPECT_THROW(tube_mesh({{0, 0, 0}, {0, 0, 1}}, std::nan("")), std::invalid_argument);
    EXPECT_THROW(tube_mesh({{0, 0, 0}, {0, 0, 1}}, 1.0, 2), std::invalid_argument);
    EXPECT_THROW(tube_mesh({{0, 0, 0}, {0, std::nan(""), 1}}, 1.0), std::invalid_argument);
}

TEST(TriangleAdjacency, EveryEdgeOfAClosedTubeFindsItsNeighbour) {
    // Rings and caps repeat positions: the neighbour across each edge is found by position, and
    // it is a different triangle holding the edge the other way round.
    const TriangleMesh tube = tube_mesh({{0, 0, 0}, {0, 0, 4}, {3, 0, 4}}, 1.0, 6);
    const auto adjacency = triangle_adjacency(tube);
    ASSERT_EQ(adjacency.size(), tube.triangles.size());
    const auto same = [&](std::uint32_t a, std::uint32_t b) {  // as triangle_adjacency rounds: 1e-9 of the extent
        const grid::Point3 &p = tube.positions[a], &q = tube.positions[b];
        return std::abs(p.x - q.x) < 1e-8 && std::abs(p.y - q.y) < 1e-8 && std::abs(p.z - q.z) < 1e-8;
    };
    for (std::size_t t = 0; t < adjacency.size(); ++t)
        for (int e = 0; e < 3; ++e) {
            const std::uint32_t from = adjacency[t][2 * e], to = adjacency[t][(2 * e + 2) % 6], across = adjacency[t][2 * e + 1];
            EXPECT_FALSE(same(across, from) || same(across, to)) << "triangle " << t << " edge " << e;
            EXPECT_FALSE(same(across, tube.triangles[t][(e + 2) % 3])) << "open edge at triangle " << t << " edge " << e;
        }
}

TEST(PolylineSimplify, DropsOnlyPointsWithinTheTolerance) {
    // A vertical well through stacked centres 1 apart, wobbling by 0.01, then a bend of 5.
    const std::vector<grid::Point3> path{{0, 0, 0}, {0.01, 0, 1}, {0, 0.01, 2}, {0, 0, 3}, {5, 0, 3}};
    const std::vector<grid::Point3> kept = simplify_polyline(path, 0.05);
    ASSERT_EQ(kept.size(), 3u);  // the wobble is within 0.05 of the straight line; the bend stays
    EXPECT_EQ(kept[1].z, 3);
    EXPECT_EQ(kept[1].x, 0);
    EXPECT_EQ(simplify_polyline(path, 0.001).size(), path.size()) << "a tolerance below the wobble keeps every point";
}

TEST(TriangleAdjacency, AnOpenEdgeGetsTheTrianglesOwnThirdVertex) {
    TriangleMesh single;
    single.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    single.triangles = {{0, 1, 2}};
    const auto adjacency = triangle_adjacency(single);
    EXPECT_EQ(adjacency[0], (std::array<std::uint32_t, 6>{0, 2, 1, 0, 2, 1}));
}

}  // namespace
}  // namespace cutaway::shapes

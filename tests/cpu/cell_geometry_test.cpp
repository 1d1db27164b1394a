#include <gtest/gtest.h>

#include <cmath>

#include "grid/box_grid.h"
#include "grid/cell_geometry.h"
#include "grid/grdecl_reader.h"
#include "test_files.h"

using namespace cutaway::grid;

namespace {

CellCorners unit_cube() {
    CellCorners c;
    for (int n = 0; n < 8; ++n) c[std::size_t(n)] = {double(n & 1), double((n >> 1) & 1), double((n >> 2) & 1)};
    return c;
}

}  // namespace

TEST(CellGeometry, UnitCubeHasVolumeOneAndCentreAtHalf) {
    const CellCorners c = unit_cube();
    EXPECT_DOUBLE_EQ(signed_volume(c), 1.0);
    const Point3 centre = cell_centre(c);
    EXPECT_DOUBLE_EQ(centre.x, 0.5);
    EXPECT_DOUBLE_EQ(centre.y, 0.5);
    EXPECT_DOUBLE_EQ(centre.z, 0.5);
}

TEST(CellGeometry, MirroredCellHasNegativeSignedVolumeAndTheSameVolume) {
    CellCorners c = unit_cube();
    for (Point3& p : c) p.x = -p.x;  // a left-handed cell
    EXPECT_DOUBLE_EQ(signed_volume(c), -1.0);
    EXPECT_DOUBLE_EQ(cell_volume(c), 1.0);
}

TEST(CellGeometry, BilinearTopGivesTheMeanHeightExactly) {
    // Vertical unit columns with a bilinear (non-planar) bottom at depths h0..h3: the exact
    // volume is the integral of the bilinear height over the unit square, the mean of the four.
    CellCorners c = unit_cube();
    const double h[4] = {1.0, 3.0, 2.0, 7.5};
    for (int n = 4; n < 8; ++n) c[std::size_t(n)].z = h[n - 4];
    EXPECT_NEAR(signed_volume(c), (1.0 + 3.0 + 2.0 + 7.5) / 4.0, 1e-14);
}

TEST(CellGeometry, ShearedCellKeepsItsVolume) {
    // Shearing along x with z (tilted pillars) preserves volume: 2 x 3 x 4 box sheared by 0.7.
    CellCorners c;
    for (int n = 0; n < 8; ++n) {
        const double x = 2.0 * (n & 1), y = 3.0 * ((n >> 1) & 1), z = 4.0 * ((n >> 2) & 1);
        c[std::size_t(n)] = {x + 0.7 * z, y, z};
    }
    EXPECT_NEAR(signed_volume(c), 24.0, 1e-12);
}

TEST(CellGeometry, PointOnTiltedPillarIsLinearInDepth) {
    const Pillar p{{0, 0, 100}, {10, 20, 200}};
    const Point3 q = point_on_pillar(p, 150);
    EXPECT_DOUBLE_EQ(q.x, 5);
    EXPECT_DOUBLE_EQ(q.y, 10);
    const Pillar flat{{4, 5, 100}, {9, 9, 100}};  // degenerate pillar: vertical through its top
    EXPECT_DOUBLE_EQ(point_on_pillar(flat, 130).x, 4);
}

TEST(CellGeometry, UnfaultedBoxVolumesSumToTheBoxVolume) {
    BoxGridSpec spec;
    spec.dims = {7, 5, 4};
    spec.cell_size = {50, 80, 3};
    const CornerPointGrid grid = make_box_grid(spec);
    double total = 0;
    for (int k = 0; k < 4; ++k)
        for (int j = 0; j < 5; ++j)
            for (int i = 0; i < 7; ++i) total += cell_volume(cell_corners(grid, i, j, k));
    // Each cell volume is exact up to a few ulps of its 12,000 m^3; 140 cells sum well within 1e-9.
    EXPECT_NEAR(total, 7 * 50.0 * 5 * 80.0 * 4 * 3.0, 1e-9 * total);
    const Box3 box = grid_bounds(grid);
    EXPECT_DOUBLE_EQ(box.max.x - box.min.x, 350);
    EXPECT_DOUBLE_EQ(box.max.z - box.min.z, 12);
}

TEST(CellGeometry, ReekFirstCellMatchesOpmNumbers) {
    // DATA.md quotes OPM's EclipseGrid for cell (0,0,0): volume 108688.95, centre
    // (110.166, 8779.689, 1727.649), printed to those digits; we agree to the printed precision.
    const CornerPointGrid grid = load_grdecl({cutaway::test::reek_grid()});
    const CellCorners c = cell_corners(grid, 0, 0, 0);
    EXPECT_NEAR(cell_volume(c), 108688.95, 0.005);
    const Point3 centre = cell_centre(c);
    EXPECT_NEAR(centre.x, 110.166, 5e-4);
    EXPECT_NEAR(centre.y, 8779.689, 5e-4);
    EXPECT_NEAR(centre.z, 1727.649, 5e-4);
}

TEST(CellGeometry, ShapesArePinchedInvertedOrRegular) {
    BoxGridSpec spec;
    spec.dims = {1, 1, 1};
    const CornerPointGrid regular = make_box_grid(spec);
    EXPECT_EQ(classify_shape(regular, 0, 0, 0, 1e-9), CellShape::regular);

    std::vector<double> flat(8, 1000.0);
    const CornerPointGrid pinched({1, 1, 1}, regular.coord(), ZcornStore::from_values({1, 1, 1}, flat), {});
    EXPECT_EQ(classify_shape(pinched, 0, 0, 0, 1e-9), CellShape::pinched);
    EXPECT_EQ(cell_volume(cell_corners(pinched, 0, 0, 0)), 0.0);

    std::vector<double> crossed = {1000, 1000, 1000, 1000, 1010, 1010, 990, 1010};  // corner 2 crossed
    const CornerPointGrid inverted({1, 1, 1}, regular.coord(), ZcornStore::from_values({1, 1, 1}, crossed), {});
    EXPECT_EQ(classify_shape(inverted, 0, 0, 0, 1e-9), CellShape::inverted);
}

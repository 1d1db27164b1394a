#include <gtest/gtest.h>

#include "grid/box_grid.h"
#include "grid/face_classification.h"
#include "grid/fault_cover.h"
#include "grid/grdecl_reader.h"
#include "test_files.h"

using namespace cutaway::grid;

TEST(FaceClassification, UnfaultedBoxHasNoFaultFaces) {
    BoxGridSpec spec;
    spec.dims = {6, 4, 3};
    const FaceCounts n = FaceClassification(make_box_grid(spec), 1e-6).counts();
    EXPECT_EQ(n.fault, 0u);
    // Interior faces: (nx-1)ny nz + nx(ny-1)nz + nx ny(nz-1); shell: the box's surface.
    EXPECT_EQ(n.interior, 5u * 4 * 3 + 6u * 3 * 3 + 6u * 4 * 2);
    EXPECT_EQ(n.shell, 2u * (6 * 4 + 4 * 3 + 6 * 3));
}

TEST(FaceClassification, FaultFacesAppearExactlyWhereTheThrowIs) {
    BoxGridSpec spec;
    spec.dims = {6, 4, 3};
    spec.fault_i = 2;  // cells with i >= 2 thrown down by 4 m
    spec.fault_throw = 4;
    const CornerPointGrid grid = make_box_grid(spec);
    const FaceClassification faces(grid, 1e-6);
    const GridDims& d = grid.dims();
    for (int k = 0; k < d.nz; ++k)
        for (int j = 0; j < d.ny; ++j)
            for (int i = 0; i < d.nx; ++i)
                for (int side = 0; side < 6; ++side) {
                    const FaceClass c = faces.at(d.cell_index(i, j, k), FaceSide(side));
                    const bool on_fault = (i == 1 && side == int(FaceSide::i_plus)) || (i == 2 && side == int(FaceSide::i_minus));
                    EXPECT_EQ(c == FaceClass::fault, on_fault) << i << ',' << j << ',' << k << " side " << side;
                }
    EXPECT_EQ(faces.counts().fault, std::size_t(d.ny * d.nz));
}

TEST(FaceClassification, InactiveNeighboursMakeShellFaces) {
    BoxGridSpec spec;
    spec.dims = {3, 1, 1};
    const CornerPointGrid box = make_box_grid(spec);
    const CornerPointGrid grid(box.dims(), box.coord(), box.zcorn(), {1, 0, 1});
    const FaceClassification faces(grid, 1e-6);
    EXPECT_EQ(faces.at(0, FaceSide::i_plus), FaceClass::shell);
    EXPECT_EQ(faces.at(1, FaceSide::i_minus), FaceClass::none);
    EXPECT_EQ(faces.counts().interior, 0u);
    EXPECT_EQ(faces.counts().shell, 12u);
}

TEST(FaceClassification, ReekHasFaultFacesOnlyBetweenActiveCells) {
    const CornerPointGrid grid = load_grdecl({cutaway::test::reek_grid()});
    const FaceClassification faces(grid, default_face_tolerance(grid));
    EXPECT_GT(faces.counts().fault, 1000u);  // the Reek model is heavily faulted
    const GridDims& d = grid.dims();
    for (std::size_t cell = 0; cell < grid.cell_count(); ++cell)
        for (int side = 0; side < 6; ++side) {
            const FaceClass c = faces.at(cell, FaceSide(side));
            ASSERT_EQ(c == FaceClass::none, !grid.active(cell));
            if (c != FaceClass::fault) continue;
            const CellIjk ijk = cell_ijk(d, cell);
            const int axis = side / 2, step = side % 2 ? 1 : -1;
            const int ni = ijk.i + (axis == 0) * step, nj = ijk.j + (axis == 1) * step, nk = ijk.k + (axis == 2) * step;
            ASSERT_TRUE(d.contains(ni, nj, nk) && grid.active(d.cell_index(ni, nj, nk)));
        }
}

TEST(FaultCover, OnlyTheFaultFacesTheThrowLeavesPartlyOpenBoundTheModel) {
    // 3 layers of 10 m; cells with i >= 2 thrown down 4 m. The up-thrown side's top layer sticks out
    // 4 m above the other side's top, the down-thrown side's bottom layer 4 m below the other's
    // bottom: those two faces are partly open; the 4 others of each row lie against the stack across.
    BoxGridSpec spec;
    spec.dims = {4, 2, 3};
    spec.fault_i = 2;
    spec.fault_throw = 4;
    const CornerPointGrid grid = make_box_grid(spec);
    const std::vector<bool> active(grid.cell_count(), true);
    const GridDims& d = grid.dims();
    for (int j = 0; j < d.ny; ++j)
        for (int k = 0; k < d.nz; ++k) {
            EXPECT_EQ(face_covered_across(grid.zcorn(), active, 1, j, k, FaceSide::i_plus), k > 0) << j << ',' << k;
            EXPECT_EQ(face_covered_across(grid.zcorn(), active, 2, j, k, FaceSide::i_minus), k < 2) << j << ',' << k;
            // Interior faces against an unfaulted neighbour are covered by it alone; K faces never count.
            EXPECT_TRUE(face_covered_across(grid.zcorn(), active, 0, j, k, FaceSide::i_plus));
            EXPECT_FALSE(face_covered_across(grid.zcorn(), active, 1, j, k, FaceSide::k_plus));
        }
    EXPECT_FALSE(face_covered_across(grid.zcorn(), active, 3, 0, 1, FaceSide::i_plus)) << "the grid's edge";

    // An inactive cell in the stack across breaks it: (1, 0, 1) spans 1010-1020 m, its neighbour
    // (2, 0, 1) 1014-1024 m, and the 4 m above it needs (2, 0, 0).
    std::vector<bool> holed = active;
    holed[d.cell_index(2, 0, 0)] = false;
    EXPECT_FALSE(face_covered_across(grid.zcorn(), holed, 1, 0, 1, FaceSide::i_plus));
    EXPECT_TRUE(face_covered_across(grid.zcorn(), holed, 1, 0, 2, FaceSide::i_plus)) << "1020-1030 lies within 1014-1034";
    EXPECT_TRUE(face_covered_across(grid.zcorn(), holed, 1, 1, 1, FaceSide::i_plus)) << "the other row is whole";
}

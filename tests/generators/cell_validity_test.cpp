// The exact orientation check on hand-made cells.
#include <gtest/gtest.h>

#include "generators/cell_validity.h"

namespace cutaway::generators {
namespace {

grid::CellCorners box(double top, double bottom) {
    grid::CellCorners c;
    for (int b = 0; b < 8; ++b)
        c[std::size_t(b)] = {double(b & 1) * 10, double(b >> 1 & 1) * 10, (b & 4) ? bottom : top};
    return c;
}

TEST(CellValidity, BoxIsValid) { EXPECT_EQ(check_cell(box(0, 5)), CellValidity::valid); }

TEST(CellValidity, ZeroThicknessIsPinched) { EXPECT_EQ(check_cell(box(3, 3)), CellValidity::pinched); }

TEST(CellValidity, BottomAboveTopIsInverted) { EXPECT_EQ(check_cell(box(5, 0)), CellValidity::inverted); }

TEST(CellValidity, WedgeIsValid) {
    grid::CellCorners c = box(0, 5);
    c[5].z = c[1].z;  // the i+1, j pillar edge pinches
    c[7].z = c[3].z;
    EXPECT_EQ(check_cell(c), CellValidity::valid);
}

TEST(CellValidity, OneCrossedEdgeIsInverted) {
    grid::CellCorners c = box(0, 5);
    c[6].z = -2;  // bottom corner of the i, j+1 edge above its top
    EXPECT_EQ(check_cell(c), CellValidity::inverted);
}

TEST(CellValidity, CollapsedSideIsDegenerate) {
    grid::CellCorners c = box(0, 5);
    c[1] = c[0];  // the i+1 pillar meets the i pillar on the j- side
    c[5] = c[4];
    EXPECT_NE(check_cell(c), CellValidity::valid);
}

}  // namespace
}  // namespace cutaway::generators

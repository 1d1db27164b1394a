// Enclosed pockets of inactive cells (grid/enclosed_pockets.h): a group of inactive cells counts as
// walled in only when it touches no side of the grid and all of its faces meet their neighbours'
// (no fault throw, no gap between layers); anything else may open to the outside, so it does not.
#include <gtest/gtest.h>

#include <vector>

#include "grid/box_grid.h"
#include "grid/enclosed_pockets.h"

using namespace cutaway::grid;

namespace {

constexpr double tolerance = 1e-6;

ZcornStore box_zcorn(GridDims dims, int fault_i = 0, double fault_throw = 0) {
    BoxGridSpec spec;
    spec.dims = dims;
    spec.fault_i = fault_i;
    spec.fault_throw = fault_throw;
    return make_box_grid(spec).zcorn();
}

/// Every cell active but `inactive`.
std::vector<bool> active_but(const GridDims& d, const std::vector<CellIjk>& inactive) {
    std::vector<bool> active(d.cell_count(), true);
    for (const CellIjk& c : inactive) active[d.cell_index(c.i, c.j, c.k)] = false;
    return active;
}

std::size_t count(const std::vector<bool>& flags) {
    std::size_t n = 0;
    for (const bool f : flags) n += f;
    return n;
}

}  // namespace

TEST(EnclosedPockets, AGroupInsideAnUnfaultedBoxIsWalledIn) {
    const GridDims d{6, 6, 5};
    const std::vector<CellIjk> pocket{{2, 2, 2}, {3, 2, 2}, {3, 3, 2}, {3, 3, 3}};
    const std::vector<bool> enclosed = enclosed_inactive_cells(box_zcorn(d), active_but(d, pocket), tolerance);
    for (const CellIjk& c : pocket) EXPECT_TRUE(enclosed[d.cell_index(c.i, c.j, c.k)]) << c.i << ',' << c.j << ',' << c.k;
    EXPECT_EQ(count(enclosed), pocket.size());  // never an active cell
}

TEST(EnclosedPockets, AGroupReachingASideOfTheGridIsOpen) {
    const GridDims d{6, 6, 5};
    // A channel from the centre to the top layer (k = 0), and a lone cell on the I- side.
    const std::vector<CellIjk> open{{2, 2, 2}, {2, 2, 1}, {2, 2, 0}, {0, 3, 2}};
    const std::vector<CellIjk> walled{{4, 4, 3}};
    std::vector<CellIjk> inactive = open;
    inactive.insert(inactive.end(), walled.begin(), walled.end());
    const std::vector<bool> enclosed = enclosed_inactive_cells(box_zcorn(d), active_but(d, inactive), tolerance);
    for (const CellIjk& c : open) EXPECT_FALSE(enclosed[d.cell_index(c.i, c.j, c.k)]) << c.i << ',' << c.j << ',' << c.k;
    EXPECT_TRUE(enclosed[d.cell_index(4, 4, 3)]);
    EXPECT_EQ(count(enclosed), 1u);
}

TEST(EnclosedPockets, AGroupAtAFaultMayOpenAcrossItAndIsNotWalledIn) {
    const GridDims d{7, 5, 5};
    // Cells with i >= 3 thrown down by half a layer: the pocket at i = 2 touches the fault, the
    // one at i = 5 does not.
    const ZcornStore z = box_zcorn(d, 3, 5.0);
    const std::vector<bool> enclosed = enclosed_inactive_cells(z, active_but(d, {{2, 2, 2}, {5, 2, 2}}), tolerance);
    EXPECT_FALSE(enclosed[d.cell_index(2, 2, 2)]);
    EXPECT_TRUE(enclosed[d.cell_index(5, 2, 2)]);
}

TEST(EnclosedPockets, AGapBetweenLayersOpensAGroup) {
    const GridDims d{5, 5, 5};
    const ZcornStore box = box_zcorn(d);
    // The bottom of cell (2, 2, 1) lifted by 1 m: a gap between it and the pocket cell below.
    std::vector<double> values(d.zcorn_value_count());
    for (std::size_t v = 0; v < values.size(); ++v) values[v] = box.value(v);
    const std::size_t layer = std::size_t(4 * d.nx * d.ny);  // depths of one plane
    const std::size_t bottom_plane = 2 * 1 + 1;                // cell layer 1, bottom
    for (int row = 4; row <= 5; ++row)
        for (int col = 4; col <= 5; ++col) values[bottom_plane * layer + std::size_t(row * 2 * d.nx + col)] -= 1.0;
    const ZcornStore gapped = ZcornStore::from_values(d, values);
    const std::vector<bool> active = active_but(d, {{2, 2, 2}});
    EXPECT_TRUE(enclosed_inactive_cells(box, active, tolerance)[d.cell_index(2, 2, 2)]);
    EXPECT_FALSE(enclosed_inactive_cells(gapped, active, tolerance)[d.cell_index(2, 2, 2)]);
}

TEST(EnclosedPockets, AnAllActiveGridHasNone) {
    const GridDims d{3, 3, 3};
    EXPECT_EQ(count(enclosed_inactive_cells(box_zcorn(d), std::vector<bool>(d.cell_count(), true), tolerance)), 0u);
}

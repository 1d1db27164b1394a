// CPU parts of the output-sensitive renderer: the IJK bricks the culling pass walks, and the
// --cell-ids encoding.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <limits>

#include "cutaway/active_cell_rank.h"
#include "cutaway/cell_id_image.h"
#include "cutaway/grid_layout.h"
#include "cutaway/visibility/cell_bricks.h"
#include "grid/cell_geometry.h"
#include "grid/grdecl_reader.h"

namespace cutaway {
namespace {

grid::CornerPointGrid reek_grid() {
    return grid::load_grdecl({std::string(CUTAWAY_SHARED_DATA) + "/grdecl/reek/reek_sim_grid.grdecl"});
}

// Everything the renderer's set-up computes per cell on the CPU (the bounds, the face classes,
// the per-cell records, the bricks) runs on every core (OpenMP); one thread and four (more than
// this machine's cores, so the work is split whatever the machine) must give the same values.
TEST(SetUpThreads, OneThreadAndFourBuildTheSameRecords) {
    const grid::CornerPointGrid grid = reek_grid();
    struct Built {
        grid::Box3 bounds;
        std::vector<grid::FaceClass> faces;
        pipeline::GridLayout layout;
        pipeline::CellBricks bricks;
    };
    const auto build = [&](int threads) {
        const int before = omp_get_max_threads();
        omp_set_num_threads(threads);
        Built b{grid::grid_bounds(grid), {}, {}, {}};
        const pipeline::ModelFrame frame = pipeline::make_model_frame(grid, b.bounds, 0.0);
        const grid::FaceClassification classes(grid, grid::face_tolerance_for(b.bounds));
        for (std::size_t cell = 0; cell < grid.cell_count(); ++cell)
            for (int side = 0; side < 6; ++side) b.faces.push_back(classes.at(cell, grid::FaceSide(side)));
        b.layout = pipeline::build_grid_layout(grid, classes, frame);
        b.bricks = pipeline::build_cell_bricks(grid, frame);
        omp_set_num_threads(before);
        return b;
    };
    const Built one = build(1), four = build(4);
    for (const auto& [a, b] : {std::pair(one.bounds.min, four.bounds.min), std::pair(one.bounds.max, four.bounds.max)}) {
        EXPECT_EQ(a.x, b.x);
        EXPECT_EQ(a.y, b.y);
        EXPECT_EQ(a.z, b.z);
    }
    EXPECT_EQ(one.faces, four.faces);
    EXPECT_EQ(one.layout.cells, four.layout.cells);
    EXPECT_EQ(one.layout.face_classes, four.layout.face_classes);
    EXPECT_EQ(one.bricks.cells, four.bricks.cells);
    EXPECT_EQ(one.bricks.begin, four.bricks.begin);
    EXPECT_EQ(one.bricks.boxes, four.bricks.boxes);
}

// The renderer answers Eclipse -> compact lookups (the bricks, frustum-clusters' boxes) from ACTNUM
// with a count per block of 64 cells instead of a table: reek has inactive cells, so the counts
// within a block matter. The layout's cells are the compact -> Eclipse map.
TEST(ActiveCellRank, EqualsTheLayoutsCompactIndexOfEveryActiveCell) {
    const grid::CornerPointGrid grid = reek_grid();
    ASSERT_LT(grid.active_count(), grid.cell_count());
    const pipeline::GridLayout layout =
        pipeline::build_grid_layout(grid, grid::FaceClassification(grid, grid::default_face_tolerance(grid)),
                                    pipeline::make_model_frame(grid, 0.0));
    const pipeline::ActiveCellRank rank(grid.actnum());
    std::size_t wrong = 0;
    ASSERT_EQ(layout.cells.size(), grid.active_count());
    for (std::uint32_t compact = 0; compact < layout.cells.size(); ++compact)
        wrong += rank(layout.cells[compact] & 0x7fffffffu) != compact;
    EXPECT_EQ(wrong, 0u);
}

TEST(CellBricks, EveryActiveCellInExactlyOneBrickWhoseBoxHoldsItsCorners) {
    const grid::CornerPointGrid grid = reek_grid();
    const pipeline::ModelFrame frame = pipeline::make_model_frame(grid, 0.0);
    const grid::FaceClassification classes(grid, grid::default_face_tolerance(grid));
    const pipeline::GridLayout layout = pipeline::build_grid_layout(grid, classes, frame);
    const pipeline::CellBricks bricks = pipeline::build_cell_bricks(grid, frame);

    ASSERT_EQ(bricks.cells.size(), grid.active_count());
    ASSERT_EQ(bricks.boxes.size(), 8 * bricks.brick_count());
    std::vector<int> seen(grid.active_count(), 0);
    for (std::size_t b = 0; b < bricks.brick_count(); ++b) {
        ASSERT_LT(bricks.begin[b], bricks.begin[b + 1]) << "brick " << b << " is empty";
        ASSERT_LE(bricks.begin[b + 1] - bricks.begin[b], std::uint32_t(pipeline::brick_side * pipeline::brick_side * pipeline::brick_side));
        const glm::vec3 lo(bricks.boxes[8 * b], bricks.boxes[8 * b + 1], bricks.boxes[8 * b + 2]);
        const glm::vec3 hi(bricks.boxes[8 * b + 4], bricks.boxes[8 * b + 5], bricks.boxes[8 * b + 6]);
        grid::CellIjk first{};
        for (std::uint32_t slot = bricks.begin[b]; slot < bricks.begin[b + 1]; ++slot) {
            const std::uint32_t compact = bricks.cells[slot];
            ++seen.at(compact);
            const grid::CellIjk c = grid::cell_ijk(grid.dims(), layout.cells[compact] & 0x7fffffffu);
            if (slot == bricks.begin[b]) first = c;
            // One 4x4x4 IJK block per brick.
            EXPECT_EQ(c.i / pipeline::brick_side, first.i / pipeline::brick_side);
            EXPECT_EQ(c.j / pipeline::brick_side, first.j / pipeline::brick_side);
            EXPECT_EQ(c.k / pipeline::brick_side, first.k / pipeline::brick_side);
            for (const grid::Point3& p : grid::cell_corners(grid, c.i, c.j, c.k)) {
                const glm::vec3 r = frame.to_render(p);
                EXPECT_TRUE(glm::all(glm::greaterThanEqual(r, lo)) && glm::all(glm::lessThanEqual(r, hi)))
                    << "cell " << c.i << "," << c.j << "," << c.k << " outside its brick's box";
            }
        }
    }
    EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; }));
}

TEST(CellIdImage, EncodesEclipseIndexPlusOneLittleEndianAndFlipsRows) {
    const std::vector<std::uint32_t> ids{0, 1, 256, 65536, 16777216, std::numeric_limits<std::uint32_t>::max()};
    const gl::RgbaImage image = pipeline::encode_cell_ids(ids, 3, 2);
    // GL rows run bottom to top, PNG rows top to bottom: the PNG's first row is GL row 1.
    EXPECT_EQ(image.at(0, 0)[2], 1);  // 65536: B = 1
    EXPECT_EQ(image.at(1, 0)[3], 1);  // 16777216: A = 1
    EXPECT_EQ(image.at(2, 0)[0], 255);
    EXPECT_EQ(image.at(0, 1)[0] + image.at(0, 1)[1] + image.at(0, 1)[2] + image.at(0, 1)[3], 0);  // 0: no cell
    EXPECT_EQ(image.at(1, 1)[0], 1);  // 1: R = 1
    EXPECT_EQ(image.at(2, 1)[1], 1);  // 256: G = 1
    EXPECT_EQ(pipeline::decode_cell_ids(image), ids);
    EXPECT_THROW(pipeline::encode_cell_ids(ids, 4, 2), std::invalid_argument);
}

}  // namespace
}  // namespace cutaway

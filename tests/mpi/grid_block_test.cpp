// Rank slabs and grid blocks (src/distributed/), on the CPU: the slabs cover the model once with
// active cells in each, and a block's cells keep their corners and, thanks to the halo, the face
// classes the whole model gives them (a slab boundary is not drawn as shell).
#include <gtest/gtest.h>

#include <stdexcept>

#include "cutaway/model_frame.h"
#include "distributed/global_model.h"
#include "distributed/grid_block.h"
#include "distributed/rank_blocks.h"
#include "generators/generator.h"
#include "grid/cell_geometry.h"

namespace cutaway::test {
namespace {

grid::CornerPointGrid faulted_model() {
    generators::GeneratorParameters p;
    p.dims = {14, 11, 9};
    p.fault_count = 3;
    p.inactive_fraction = 0.2;
    p.seed = 7;
    generators::ProgressLog quiet(nullptr);
    return generators::generate_model(p, quiet).grid;
}

int extent(const grid::IjkBox& b, distributed::SlabAxis axis) {
    return axis == distributed::SlabAxis::i ? b.i1 - b.i0 + 1 : axis == distributed::SlabAxis::j ? b.j1 - b.j0 + 1 : b.k1 - b.k0 + 1;
}

TEST(RankSlabs, CoverTheModelOnceWithActiveCellsInEach) {
    const grid::CornerPointGrid grid = faulted_model();
    for (auto axis : {distributed::SlabAxis::i, distributed::SlabAxis::j, distributed::SlabAxis::k})
        for (int ranks = 1; ranks <= 5; ++ranks) {
            const std::vector<grid::IjkBox> boxes = distributed::split_into_slabs(grid, ranks, axis);
            ASSERT_EQ(boxes.size(), std::size_t(ranks));
            int layers = 0;
            std::size_t active = 0;
            for (const grid::IjkBox& box : boxes) {
                layers += extent(box, axis);
                std::size_t in_box = 0;
                for (std::size_t c = 0; c < grid.cell_count(); ++c)
                    in_box += grid.active(c) && box.contains(grid::cell_ijk(grid.dims(), c)) ? 1 : 0;
                EXPECT_GT(in_box, 0u);
                active += in_box;
            }
            const grid::GridDims& d = grid.dims();
            EXPECT_EQ(layers, axis == distributed::SlabAxis::i ? d.nx : axis == distributed::SlabAxis::j ? d.ny : d.nz);
            EXPECT_EQ(active, grid.active_count());
        }
}

TEST(RankSlabs, MoreRanksThanLayersIsRefused) {
    const grid::CornerPointGrid grid = faulted_model();
    EXPECT_THROW(distributed::split_into_slabs(grid, 10, distributed::SlabAxis::k), std::invalid_argument);
    EXPECT_THROW(distributed::split_into_slabs(grid, 0, distributed::SlabAxis::k), std::invalid_argument);
}

TEST(GridBlock, KeepsCornersActnumAndTheWholeModelsFaceClasses) {
    const grid::CornerPointGrid whole = faulted_model();
    const double tolerance = grid::default_face_tolerance(whole);
    const grid::FaceClassification whole_classes(whole, tolerance);
    std::size_t boundary_faces = 0;
    for (auto axis : {distributed::SlabAxis::i, distributed::SlabAxis::j, distributed::SlabAxis::k})
        for (const grid::IjkBox& box : distributed::split_into_slabs(whole, 3, axis)) {
            const distributed::GridBlock block = distributed::make_grid_block(whole, box, tolerance);
            for (std::size_t c = 0; c < block.grid.cell_count(); ++c) {
                const std::uint32_t w = block.whole_id(std::uint32_t(c + 1)) - 1;
                const grid::CellIjk b = grid::cell_ijk(block.grid.dims(), c), g = grid::cell_ijk(whole.dims(), w);
                ASSERT_EQ(block.grid.active(c), whole.active(w));
                for (int corner = 0; corner < 8; ++corner)
                    ASSERT_EQ(block.grid.zcorn().corner_depth(b.i, b.j, b.k, corner), whole.zcorn().corner_depth(g.i, g.j, g.k, corner));
                const grid::CellCorners mine = grid::cell_corners(block.grid, b.i, b.j, b.k);
                const grid::CellCorners theirs = grid::cell_corners(whole, g.i, g.j, g.k);
                for (int corner = 0; corner < 8; ++corner) {
                    ASSERT_EQ(mine[std::size_t(corner)].x, theirs[std::size_t(corner)].x);
                    ASSERT_EQ(mine[std::size_t(corner)].y, theirs[std::size_t(corner)].y);
                    ASSERT_EQ(mine[std::size_t(corner)].z, theirs[std::size_t(corner)].z);
                }
                for (int side = 0; side < 6; ++side) {
                    ASSERT_EQ(block.classes.at(c, grid::FaceSide(side)), whole_classes.at(w, grid::FaceSide(side)))
                        << "cell " << g.i << "," << g.j << "," << g.k << " side " << side;
                    const bool on_boundary = (side == 0 && b.i == 0 && g.i > 0) || (side == 2 && b.j == 0 && g.j > 0) ||
                                             (side == 4 && b.k == 0 && g.k > 0);
                    boundary_faces += on_boundary && block.grid.active(c) ? 1 : 0;
                }
            }
        }
    EXPECT_GT(boundary_faces, 0u);  // the slab boundaries were exercised
}

TEST(GridBlock, WholeIdsMapBackAndZeroStaysZero) {
    const grid::CornerPointGrid whole = faulted_model();
    const grid::IjkBox box{2, 3, 4, 9, 8, 6};
    const distributed::GridBlock block = distributed::make_grid_block(whole, box, grid::default_face_tolerance(whole));
    EXPECT_EQ(block.whole_id(0), 0u);
    EXPECT_EQ(block.whole_id(1), std::uint32_t(whole.dims().cell_index(2, 3, 4) + 1));
    EXPECT_EQ(block.whole_id(std::uint32_t(block.grid.cell_count())), std::uint32_t(whole.dims().cell_index(9, 8, 6) + 1));
}

}  // namespace
}  // namespace cutaway::test

namespace cutaway::test {
namespace {

void expect_same_frame(const pipeline::ModelFrame& a, const pipeline::ModelFrame& b) {
    EXPECT_EQ(a.centre.x, b.centre.x);
    EXPECT_EQ(a.centre.y, b.centre.y);
    EXPECT_EQ(a.centre.z, b.centre.z);
    EXPECT_EQ(a.z_scale, b.z_scale);
    EXPECT_EQ(a.up_sign, b.up_sign);
    EXPECT_EQ(a.render_min, b.render_min);
    EXPECT_EQ(a.render_max, b.render_max);
    ASSERT_EQ(a.outline.size(), b.outline.size());
    for (std::size_t p = 0; p < a.outline.size(); ++p) EXPECT_EQ(a.outline[p], b.outline[p]) << "outline point " << p;
}

// One process is an MPI session of one rank: the global frame of the whole model as its one part,
// and of every block with its halo merged by hand (as the ranks' collectives merge them), equal
// make_model_frame of the whole model.
TEST(GlobalModel, FrameOfTheBlocksEqualsTheWholeModelsFrame) {
    const distributed::MpiSession mpi;
    const grid::CornerPointGrid whole = faulted_model();
    const pipeline::ModelFrame expected = pipeline::make_model_frame(whole, 0.0);
    const distributed::ModelPart all{whole, grid::IjkBox::whole(whole.dims()), whole.dims()};
    const grid::Box3 bounds = distributed::global_bounds(mpi, all);
    expect_same_frame(distributed::global_model_frame(mpi, all, bounds, 0.0), expected);
    EXPECT_EQ(grid::face_tolerance_for(bounds), grid::default_face_tolerance(whole));
}

}  // namespace
}  // namespace cutaway::test

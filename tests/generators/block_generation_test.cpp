// A block generated alone (generate_block) equals the same block cut from the whole generated
// model, array by array and bit for bit: COORD, ZCORN, ACTNUM, PORO, PERMX, NTG and FACIES, for
// slabs along I, J and K as 2 and 4 ranks split the model, each also with its one-cell halo, and
// for boxes cut on every axis. The model is faulted, has pinch-outs and clustered inactive cells
// (both thresholds are quantiles over the whole model, streamed by a block).
#include <gtest/gtest.h>

#include "../support/block_checks.h"
#include "generator_test_support.h"

namespace cutaway::generators {
namespace {

void expect_generated_block(const grid::CornerPointGrid& whole, const grid::IjkBox& box, const GeneratorParameters& p) {
    SCOPED_TRACE(test::box_text(box));
    ProgressLog quiet(nullptr);
    const GeneratedModel block = generate_block(p, box, quiet);
    test::expect_block_equals_cut(block.grid, whole, box);
    EXPECT_EQ(*block.grid.int_property("FACIES"), grid::box_values(*whole.int_property("FACIES"), whole.dims(), box));
    EXPECT_EQ(block.report.active_cells, block.grid.active_count());
}

/// Four faults, 5% pinched and 20% clustered inactive cells, dimensions no split divides evenly.
GeneratorParameters faulted_with_inactive_cells() {
    GeneratorParameters p = testing::small_parameters();
    p.dims = {17, 13, 11};
    p.fault_count = 4;
    p.pinch_out_fraction = 0.05, p.inactive_fraction = 0.2;
    return p;
}

TEST(BlockGeneration, SlabsWithHalosEqualTheWholeModelsBlocks) {
    const GeneratorParameters p = faulted_with_inactive_cells();
    const grid::CornerPointGrid whole = testing::generate_quietly(p).grid;
    ASSERT_LT(whole.active_count(), whole.cell_count()) << "expected inactive cells";
    for (int axis = 0; axis < 3; ++axis)
        for (int parts : {2, 4})
            for (int part = 0; part < parts; ++part) {
                const grid::IjkBox box = test::equal_layer_slab(whole.dims(), axis, part, parts);
                expect_generated_block(whole, box, p);
                expect_generated_block(whole, grid::with_halo(box, whole.dims()), p);
            }
}

TEST(BlockGeneration, BoxesCutOnEveryAxisAndTheWholeBox) {
    const GeneratorParameters p = faulted_with_inactive_cells();
    const grid::CornerPointGrid whole = testing::generate_quietly(p).grid;
    expect_generated_block(whole, {3, 2, 4, 9, 10, 6}, p);
    expect_generated_block(whole, {16, 12, 10, 16, 12, 10}, p);
    expect_generated_block(whole, grid::IjkBox::whole(p.dims), p);
}

TEST(BlockGeneration, BoxOutsideTheGridIsRefused) {
    ProgressLog quiet(nullptr);
    const GeneratorParameters p = faulted_with_inactive_cells();
    EXPECT_THROW(generate_block(p, {0, 0, 0, p.dims.nx, 1, 1}, quiet), std::invalid_argument);
    EXPECT_THROW(generate_block(p, {2, 0, 0, 1, 1, 1}, quiet), std::invalid_argument);
}

}  // namespace
}  // namespace cutaway::generators

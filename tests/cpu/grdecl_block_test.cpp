// Reading one block of a GRDECL file (GrdeclReadOptions::block) gives the block cut from the
// whole grid (grid::extract_box), array by array and bit for bit: COORD, ZCORN, ACTNUM and the
// per-cell properties, for the slabs 2 and 4 ranks take along I, J and K (with their halos) and
// a box cut on every axis; the reader holds only the block's ZCORN, ACTNUM and properties.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "grid/grdecl_reader.h"
#include "grid/grdecl_writer.h"
#include "../support/block_checks.h"
#include "test_files.h"

namespace cutaway::test {
namespace {

std::vector<std::filesystem::path> reek_files() { return {reek_grid(), reek_poro()}; }

void expect_block_read_equals_cut(const std::vector<std::filesystem::path>& files, const grid::CornerPointGrid& whole,
                                  const grid::IjkBox& box) {
    SCOPED_TRACE(box_text(box));
    grid::GrdeclReadOptions options;
    options.block = box;
    const grid::CornerPointGrid block = grid::load_grdecl(files, options);
    expect_block_equals_cut(block, whole, box);
    EXPECT_EQ(block.metadata().mapaxes, whole.metadata().mapaxes);
}

void expect_slabs_and_boxes(const std::vector<std::filesystem::path>& files, const grid::IjkBox& inner) {
    const grid::CornerPointGrid whole = grid::load_grdecl(files);
    EXPECT_EQ(grid::read_grdecl_dims(files), whole.dims());
    for (int axis = 0; axis < 3; ++axis)
        for (int parts : {2, 4})
            for (int part = 0; part < parts; ++part) {
                const grid::IjkBox box = equal_layer_slab(whole.dims(), axis, part, parts);
                expect_block_read_equals_cut(files, whole, box);
                expect_block_read_equals_cut(files, whole, grid::with_halo(box, whole.dims()));
            }
    expect_block_read_equals_cut(files, whole, inner);
    expect_block_read_equals_cut(files, whole, grid::IjkBox::whole(whole.dims()));
}

TEST(GrdeclBlock, ReekSlabsAndABoxEqualTheWholeGridsBlocks) {
    const grid::CornerPointGrid whole = grid::load_grdecl(reek_files());
    ASSERT_LT(whole.active_count(), whole.cell_count()) << "expected inactive cells";
    expect_slabs_and_boxes(reek_files(), {5, 7, 2, 30, 50, 10});
}

TEST(GrdeclBlock, ZcornWithGapsBetweenLayers) {
    // A grid whose layers do not share their interfaces (ZCORN's full layout).
    const grid::CornerPointGrid reek = grid::load_grdecl(reek_files());
    const grid::IjkBox part{10, 20, 0, 19, 31, 13};
    grid::CornerPointGrid gapped = grid::extract_box(reek, part);
    std::vector<double> depths(gapped.dims().zcorn_value_count());
    const std::size_t plane = 4 * std::size_t(gapped.dims().nx) * std::size_t(gapped.dims().ny);
    for (std::size_t n = 0; n < depths.size(); ++n) depths[n] = gapped.zcorn().value(n) + double(n / plane % 2) * 0.25;
    grid::CornerPointGrid with_gaps(gapped.dims(), std::vector<double>(gapped.coord()),
                                    grid::ZcornStore::from_values(gapped.dims(), depths), std::vector<std::uint8_t>(gapped.actnum()));
    with_gaps.set_property("PORO", grid::box_values(*reek.property("PORO"), reek.dims(), part));
    ASSERT_FALSE(with_gaps.zcorn().is_compact());
    const ScratchDir scratch("grdecl-block");
    std::ostringstream text;
    grid::write_grdecl(text, with_gaps, {});
    const auto file = scratch.write("gapped.grdecl", text.str());
    expect_slabs_and_boxes({file}, {2, 3, 4, 7, 9, 8});
}

TEST(GrdeclBlock, BlockOutsideTheGridIsRefused) {
    grid::GrdeclReadOptions options;
    options.block = grid::IjkBox{0, 0, 0, 40, 64, 14};  // reek is 40 x 64 x 14
    EXPECT_THROW(grid::load_grdecl(reek_files(), options), grid::GrdeclError);
}

}  // namespace
}  // namespace cutaway::test

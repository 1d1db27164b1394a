#pragma once
// Shared by the block tests (generated blocks, GRDECL blocks): the slabs ranks take, and a block
// compared with the same box cut from the whole grid, array by array and bit for bit.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "grid/grid_box.h"

namespace cutaway::test {

/// Equal-layer slab `part` of `parts` along `axis` (0 = I, 1 = J, 2 = K).
inline grid::IjkBox equal_layer_slab(const grid::GridDims& d, int axis, int part, int parts) {
    grid::IjkBox box = grid::IjkBox::whole(d);
    const int layers = axis == 0 ? d.nx : axis == 1 ? d.ny : d.nz;
    (axis == 0 ? box.i0 : axis == 1 ? box.j0 : box.k0) = layers * part / parts;
    (axis == 0 ? box.i1 : axis == 1 ? box.j1 : box.k1) = layers * (part + 1) / parts - 1;
    return box;
}

inline std::string box_text(const grid::IjkBox& b) {
    return "box " + std::to_string(b.i0) + " " + std::to_string(b.j0) + " " + std::to_string(b.k0) + " to " +
           std::to_string(b.i1) + " " + std::to_string(b.j1) + " " + std::to_string(b.k1);
}

inline bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// `block` against `box` cut from `whole`: dimensions, COORD, ZCORN, ACTNUM, and every real
/// property of `whole` (bit for bit).
inline void expect_block_equals_cut(const grid::CornerPointGrid& block, const grid::CornerPointGrid& whole,
                                    const grid::IjkBox& box) {
    const grid::CornerPointGrid cut = grid::extract_box(whole, box);
    ASSERT_EQ(block.dims(), cut.dims());
    ASSERT_EQ(block.coord().size(), cut.coord().size());
    for (std::size_t n = 0; n < block.coord().size(); ++n)
        ASSERT_TRUE(same_bits(block.coord()[n], cut.coord()[n])) << "COORD value " << n;
    for (std::size_t n = 0; n < block.dims().zcorn_value_count(); ++n)
        ASSERT_TRUE(same_bits(block.zcorn().value(n), cut.zcorn().value(n))) << "ZCORN value " << n;
    EXPECT_EQ(block.actnum(), cut.actnum());
    EXPECT_EQ(block.property_names(), whole.property_names());
    for (const std::string& name : whole.property_names()) {
        const std::vector<float> expected = grid::box_values(*whole.property(name), whole.dims(), box);
        ASSERT_NE(block.property(name), nullptr) << name;
        ASSERT_EQ(block.property(name)->size(), expected.size()) << name;
        EXPECT_EQ(std::memcmp(block.property(name)->data(), expected.data(), expected.size() * sizeof(float)), 0) << name;
    }
}

}  // namespace cutaway::test

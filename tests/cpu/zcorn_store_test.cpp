#include <gtest/gtest.h>

#include <random>

#include "grid/zcorn_store.h"

using cutaway::grid::GridDims;
using cutaway::grid::ZcornStore;

namespace {

// Depths where the bottom of each layer equals the top of the next, as in most simulation grids.
std::vector<double> stacked_depths(const GridDims& d, std::mt19937& rng) {
    std::uniform_real_distribution<double> jitter(0.0, 5.0);
    std::vector<double> surfaces(std::size_t(4) * d.nx * d.ny * (d.nz + 1));
    for (std::size_t n = 0; n < surfaces.size(); ++n) surfaces[n] = double(n / (4 * d.nx * d.ny)) * 10 + jitter(rng);
    std::vector<double> zcorn;
    const std::size_t plane = std::size_t(4) * d.nx * d.ny;
    for (int k = 0; k < d.nz; ++k)
        for (int face = 0; face < 2; ++face)
            for (std::size_t o = 0; o < plane; ++o) zcorn.push_back(surfaces[std::size_t(k + face) * plane + o]);
    return zcorn;
}

void expect_reads_back(const ZcornStore& store, const std::vector<double>& values) {
    ASSERT_TRUE(store.complete());
    for (std::size_t n = 0; n < values.size(); ++n) ASSERT_EQ(store.value(n), values[n]) << "value " << n;
}

}  // namespace

TEST(ZcornStore, StackedLayersStayCompactAndReadBackExactly) {
    std::mt19937 rng(7);
    const GridDims d{3, 4, 5};
    const auto values = stacked_depths(d, rng);
    const auto store = ZcornStore::from_values(d, values);
    EXPECT_TRUE(store.is_compact());
    EXPECT_EQ(store.bytes(), ZcornStore::compact_bytes(d));
    expect_reads_back(store, values);
}

TEST(ZcornStore, AGapSwitchesToTheFullLayoutWithoutLosingAValue) {
    std::mt19937 rng(11);
    const GridDims d{3, 2, 4};
    // A gap at each position of each interface plane in turn: the switch happens mid-plane.
    for (std::size_t at : {std::size_t(0), std::size_t(5), std::size_t(23)})
        for (int interface = 1; interface < d.nz; ++interface) {
            auto values = stacked_depths(d, rng);
            values[std::size_t(2 * interface) * 24 + at] += 0.5;  // top of layer `interface` lowered
            const auto store = ZcornStore::from_values(d, values);
            EXPECT_FALSE(store.is_compact());
            expect_reads_back(store, values);
        }
}

TEST(ZcornStore, CornerDepthUsesTheZcornCornerOrder) {
    const GridDims d{2, 1, 1};
    std::vector<double> values(d.zcorn_value_count());
    for (std::size_t n = 0; n < values.size(); ++n) values[n] = double(n);
    const auto store = ZcornStore::from_values(d, values);
    // Cell (1,0,0): top plane row 0 cols 2,3; row 1 cols 2,3 (row length 4); bottom plane +8.
    EXPECT_EQ(store.corner_depth(1, 0, 0, 0), 2.0);
    EXPECT_EQ(store.corner_depth(1, 0, 0, 1), 3.0);
    EXPECT_EQ(store.corner_depth(1, 0, 0, 2), 6.0);
    EXPECT_EQ(store.corner_depth(1, 0, 0, 7), 15.0);
}

TEST(ZcornStore, RefusesTheWrongNumberOfValues) {
    EXPECT_THROW(ZcornStore::from_values(GridDims{1, 1, 1}, std::vector<double>(7)), std::invalid_argument);
}

// N*value items go in a plane at a time: the store must read back exactly what value-by-value
// pushes give, and ask before (and only before) allocating the full layout.
TEST(ZcornStore, RepeatedPushesMatchSinglePushesAndWarnBeforeExpanding) {
    const GridDims d{2, 3, 4};  // planes of 24 depths
    const std::vector<std::pair<double, std::size_t>> stacked = {{0, 30}, {1, 42}, {1, 24}, {2, 48}, {3, 48}};
    const std::vector<std::pair<double, std::size_t>> gapped = {{0, 24}, {1, 30}, {1.5, 42}, {2, 96}};
    // A gap half-way through a top plane, then +0 depths: +0 is never written (the store starts
    // zeroed), so the part of the plane after the gap must start at +0, not at the bottom above.
    const std::vector<std::pair<double, std::size_t>> zeros_after_gap = {{5, 24}, {7, 30}, {0, 138}};
    for (const auto& items : {stacked, gapped, zeros_after_gap}) {
        std::vector<double> values;
        for (const auto& [depth, count] : items) values.insert(values.end(), count, depth);
        ZcornStore store(d);
        int warnings = 0;
        bool compact_when_warned = false;
        for (const auto& [depth, count] : items)
            store.push_repeated(depth, count, [&] {
                ++warnings;
                compact_when_warned = store.is_compact();
            });
        const ZcornStore single = ZcornStore::from_values(d, values);
        EXPECT_EQ(store.is_compact(), single.is_compact());
        EXPECT_EQ(warnings, single.is_compact() ? 0 : 1);
        if (warnings) {
            EXPECT_TRUE(compact_when_warned);
        }
        expect_reads_back(store, values);
    }
}

TEST(ZcornStore, RefusalBeforeExpandingLeavesTheStoreCompact) {
    const GridDims d{2, 2, 2};  // planes of 16 depths; plane 2 differs from plane 1
    ZcornStore store(d);
    store.push_repeated(0, 32, [] {});
    EXPECT_THROW(store.push_repeated(5, 16, [] { throw std::length_error("over the limit"); }), std::length_error);
    EXPECT_TRUE(store.is_compact());
    EXPECT_EQ(store.bytes(), ZcornStore::compact_bytes(d));
}

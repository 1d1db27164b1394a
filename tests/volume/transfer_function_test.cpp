// Transfer functions, quantisation and min/max blocks: analytic values, not images.
#include <gtest/gtest.h>

#include "volume/empty_space_blocks.h"
#include "volume/level_window.h"
#include "volume/quantised_volume.h"
#include "volume/transfer_function.h"

namespace cutaway::volume {
namespace {

TEST(LayerHighlight, EquationOneWithThePaperDefaults) {
    const LayerHighlight paper;  // k = 1, r = 60, alpha_v = 1, f_v = 255
    EXPECT_DOUBLE_EQ(layer_alpha(255, paper), 1.0);
    EXPECT_DOUBLE_EQ(layer_alpha(225, paper), 0.5);
    EXPECT_DOUBLE_EQ(layer_alpha(195, paper), 0.0);  // |f - f_v| = r: the band's edge
    EXPECT_DOUBLE_EQ(layer_alpha(100, paper), 0.0);  // outside the band
}

TEST(LayerHighlight, KAlphaAndCentreScaleAsWritten) {
    const LayerHighlight layer{2, 40, 0.8, 128};
    EXPECT_DOUBLE_EQ(layer_alpha(128, layer), 0.8);
    EXPECT_DOUBLE_EQ(layer_alpha(138, layer), 0.8 * (1 - 2 * 10 / 40.0));
    EXPECT_DOUBLE_EQ(layer_alpha(118, layer), layer_alpha(138, layer));  // symmetric about f_v
    EXPECT_DOUBLE_EQ(layer_alpha(150, layer), 0.0);  // k = 2 reaches 0 at r / 2; clamped, never negative
}

TEST(PseudoColour, BlueGreenYellowRedAsTheValueRises) {
    auto expect_rgb = [](Rgba c, float r, float g, float b) {
        EXPECT_FLOAT_EQ(c.r, r);
        EXPECT_FLOAT_EQ(c.g, g);
        EXPECT_FLOAT_EQ(c.b, b);
    };
    expect_rgb(pseudo_colour(0), 0, 0, 1);
    expect_rgb(pseudo_colour(1.0 / 3), 0, 1, 0);
    expect_rgb(pseudo_colour(2.0 / 3), 1, 1, 0);
    expect_rgb(pseudo_colour(1), 1, 0, 0);
    expect_rgb(pseudo_colour(0.5), 0.5f, 1, 0);
}

TEST(TransferTable, GreyIsTheLevelWithAnOpacityRamp) {
    TransferFunctionSettings settings;
    settings.opacity = 0.2;
    const TransferTable table = build_transfer_table(settings);
    EXPECT_FLOAT_EQ(table[0].r, 0);
    EXPECT_FLOAT_EQ(table[0].a, 0);
    EXPECT_FLOAT_EQ(table[51].g, 0.2f);
    EXPECT_FLOAT_EQ(table[255].b, 1);
    EXPECT_FLOAT_EQ(table[255].a, 0.2f);
}

TEST(TransferTable, LayerUsesEquationOneForOpacityAndPseudoColours) {
    TransferFunctionSettings settings;
    settings.kind = TransferFunctionKind::layer;
    settings.scale = ColourScale::rainbow;  // the paper's colours
    const TransferTable table = build_transfer_table(settings);
    for (int level = 0; level < 256; ++level) {
        EXPECT_FLOAT_EQ(table[std::size_t(level)].a, float(layer_alpha(level, settings.layer)));
        EXPECT_FLOAT_EQ(table[std::size_t(level)].r, pseudo_colour(level / 255.0).r);
    }
}

TEST(TransferTable, WindowSpansTheColourScaleAndClampsOutside) {
    TransferFunctionSettings settings;
    settings.kind = TransferFunctionKind::pseudo;
    settings.window = {100, 150};
    settings.opacity = 0.5;
    const TransferTable table = build_transfer_table(settings);
    const Rgba low = perceptual_colour(0), high = perceptual_colour(1);
    EXPECT_FLOAT_EQ(table[0].g, low.g);      // below the window: the scale's bottom
    EXPECT_FLOAT_EQ(table[100].g, low.g);
    EXPECT_FLOAT_EQ(table[150].g, high.g);
    EXPECT_FLOAT_EQ(table[255].r, high.r);   // above: its top
    EXPECT_FLOAT_EQ(table[125].g, perceptual_colour(0.5).g);
    // Signed amplitudes: both ends opaque, the window's middle (zero amplitude) clear.
    EXPECT_FLOAT_EQ(table[100].a, 0.5f);
    EXPECT_FLOAT_EQ(table[150].a, 0.5f);
    EXPECT_FLOAT_EQ(table[125].a, 0.0f);
    settings.window = {10, 10};
    EXPECT_THROW(build_transfer_table(settings), std::invalid_argument);
}

TEST(TransferTable, PerceptualScaleIsViridis) {
    // matplotlib's viridis ends: (68, 1, 84) and (253, 231, 37); luminance rises monotonically.
    EXPECT_NEAR(perceptual_colour(0).r * 255, 68, 0.5);
    EXPECT_NEAR(perceptual_colour(0).b * 255, 84, 0.5);
    EXPECT_NEAR(perceptual_colour(1).g * 255, 231, 0.5);
    double previous = -1;
    for (int i = 0; i <= 20; ++i) {
        const Rgba c = perceptual_colour(i / 20.0);
        const double luminance = 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
        EXPECT_GT(luminance, previous);
        previous = luminance;
    }
    EXPECT_EQ(parse_colour_scale("rainbow"), ColourScale::rainbow);
    EXPECT_THROW(parse_colour_scale("jet"), std::invalid_argument);
}

TEST(LevelWindow, PercentilesOfTheSamplesNotTheirExtremes) {
    // 1000 samples: 10 at level 0, 10 at 255 (outliers), the rest spread over 100..179.
    QuantisedVolume volume;
    volume.dims = {10, 10, 10};
    for (int n = 0; n < 1000; ++n)
        volume.levels.push_back(n < 10 ? 0 : n < 20 ? 255 : std::uint8_t(100 + (n - 20) % 80));
    const LevelWindow window = percentile_window(volume);
    EXPECT_GE(window.lo, 100);
    EXPECT_LE(window.lo, 102);
    EXPECT_GE(window.hi, 177);
    EXPECT_LE(window.hi, 179);
    const LayerHighlight layer = fitted_layer(window);
    EXPECT_DOUBLE_EQ(layer.f_v, window.hi);
    EXPECT_DOUBLE_EQ(layer.r, 0.5 * (window.hi - window.lo));
    // A constant cube still gets a window two levels wide.
    volume.levels.assign(1000, 7);
    const LevelWindow constant = percentile_window(volume);
    EXPECT_DOUBLE_EQ(constant.hi - constant.lo, 2);
    EXPECT_DOUBLE_EQ(level_value(255, ValueRange{-4, 4}), 4);
    EXPECT_DOUBLE_EQ(level_value(0, ValueRange{-4, 4}), -4);
}

TEST(TransferTable, LookupIsLinearBetweenEntries) {
    const TransferTable table = build_transfer_table({});
    EXPECT_FLOAT_EQ(lookup(table, 10.5f).g, 0.5f * (table[10].g + table[11].g));
    EXPECT_FLOAT_EQ(lookup(table, 255).a, table[255].a);
    EXPECT_FLOAT_EQ(lookup(table, 300).a, table[255].a);  // clamped
}

TEST(TransferTable, RefusesImpossibleParameters) {
    TransferFunctionSettings settings;
    settings.kind = TransferFunctionKind::layer;
    settings.layer.r = 0;
    EXPECT_THROW(build_transfer_table(settings), std::invalid_argument);
    settings = {};
    settings.opacity = 1.5;
    EXPECT_THROW(build_transfer_table(settings), std::invalid_argument);
    EXPECT_THROW(parse_transfer_function("rainbow"), std::invalid_argument);
}

TEST(Quantise, RangeMapsOntoTheFullLevels) {
    const ValueRange range{-2, 2};
    EXPECT_EQ(quantise_value(-2, range), 0);
    EXPECT_EQ(quantise_value(2, range), 255);
    EXPECT_EQ(quantise_value(0, range), 128);   // 127.5 rounds up
    EXPECT_EQ(quantise_value(-9, range), 0);    // clamped
    EXPECT_EQ(quantise_value(1, ValueRange{1, 1}), 0);  // constant cube
}

/// A 12^3 volume of level 0 with one voxel at `hot`.
QuantisedVolume single_voxel(int i, int x, int t, std::uint8_t hot) {
    QuantisedVolume volume;
    volume.dims = {12, 12, 12};
    volume.levels.assign(volume.dims.count(), 0);
    volume.levels[(std::size_t(i) * 12 + std::size_t(x)) * 12 + std::size_t(t)] = hot;
    return volume;
}

TEST(EmptySpaceBlocks, MinMaxIncludeTheOneVoxelApron) {
    // Voxel 8 on every axis is the first of block 1, and the apron of block 0 (trilinear samples at
    // positions up to 8.0 read voxel 8).
    const BlockGrid grid = build_block_grid(single_voxel(8, 8, 8, 200), 4);
    EXPECT_EQ(grid.blocks.inlines, 3);
    auto max_at = [&](int bi, int bx, int bt) { return grid.max[(std::size_t(bi) * 3 + std::size_t(bx)) * 3 + std::size_t(bt)]; };
    EXPECT_EQ(max_at(2, 2, 2), 200);
    EXPECT_EQ(max_at(1, 1, 1), 200);  // apron
    EXPECT_EQ(max_at(0, 0, 0), 0);
    EXPECT_EQ(max_at(2, 0, 2), 0);
}

TEST(EmptySpaceBlocks, OccupancyFollowsTheTableOpacity) {
    const BlockGrid grid = build_block_grid(single_voxel(1, 1, 1, 250), 4);
    TransferFunctionSettings layer;
    layer.kind = TransferFunctionKind::layer;  // opacity only for levels 196..255
    const std::vector<std::uint8_t> occupied = occupied_blocks(grid, build_transfer_table(layer));
    EXPECT_EQ(occupied[0], 1);
    EXPECT_EQ(std::count(occupied.begin(), occupied.end(), 1), 1);
    TransferFunctionSettings grey;  // level 0 has opacity 0, the rest some
    const std::vector<std::uint8_t> grey_occupied = occupied_blocks(grid, build_transfer_table(grey));
    EXPECT_EQ(std::count(grey_occupied.begin(), grey_occupied.end(), 1), 1);
}

}  // namespace
}  // namespace cutaway::volume

// Image metrics on hand-made id images, where the right answer is known exactly.
#include <gtest/gtest.h>

#include <cmath>

#include "metrics/image_metrics.h"

namespace cutaway::metrics {
namespace {

struct Frame {
    int width, height;
    std::vector<std::uint32_t> cell, flags;
    Frame(int w, int h) : width(w), height(h), cell(std::size_t(w * h), 0), flags(std::size_t(w * h), 0) {}
    PixelIds ids() const { return {width, height, cell, flags}; }
    void set(int x, int y, std::uint32_t c, std::uint32_t f) {
        cell[std::size_t(y * width + x)] = c;
        flags[std::size_t(y * width + x)] = f;
    }
};

TEST(ImageMetrics, ExposureCountsPrimaryPixelsShowingTheSameCell) {
    Frame primaries(4, 1), cutaway(4, 1);
    for (int x = 0; x < 4; ++x) primaries.set(x, 0, 10, flag_primary);
    cutaway.set(0, 0, 10, flag_primary);   // visible
    cutaway.set(1, 0, 10, flag_primary);   // visible
    cutaway.set(2, 0, 11, flag_primary);   // another primary in front: not the same cell
    cutaway.set(3, 0, 10, 0);               // a secondary with the same id: not a primary pixel
    const Exposure e = primary_exposure(primaries.ids(), cutaway.ids());
    EXPECT_EQ(e.primary_pixels, 4u);
    EXPECT_EQ(e.visible, 2u);
    EXPECT_DOUBLE_EQ(e.fraction, 0.5);
}

TEST(ImageMetrics, ContextKeptIsZeroAtTheWidestCutAndOneUncut) {
    EXPECT_DOUBLE_EQ(context_kept(100, 20, 100).fraction, 1.0);
    EXPECT_DOUBLE_EQ(context_kept(20, 20, 100).fraction, 0.0);
    EXPECT_DOUBLE_EQ(context_kept(60, 20, 100).fraction, 0.5);
    EXPECT_DOUBLE_EQ(context_kept(5, 5, 5).fraction, 1.0);  // nothing to remove
}

TEST(ImageMetrics, ContextPixelsLeaveOutPrimariesFillAndBorders) {
    Frame f(4, 1);
    f.set(0, 0, 1, 0);
    f.set(1, 0, 2, flag_primary);
    f.set(2, 0, 3, flag_cut_fill);
    f.set(3, 0, 4, flag_border);
    EXPECT_EQ(context_pixels(f.ids()), 1u);
}

TEST(ImageMetrics, ContextShareIsContextOverPixelsShowingACell) {
    Frame f(5, 1);  // the last pixel stays background: left out of the model's pixels
    f.set(0, 0, 1, 0);
    f.set(1, 0, 2, 0);
    f.set(2, 0, 3, flag_primary);
    f.set(3, 0, 4, flag_cut_fill);
    const ContextShare share = context_share(f.ids());
    EXPECT_EQ(share.context, 2u);
    EXPECT_EQ(share.model, 4u);
    EXPECT_DOUBLE_EQ(share.fraction, 0.5);
    EXPECT_DOUBLE_EQ(context_share(Frame(3, 1).ids()).fraction, 0.0);  // no cell: no share, no division by zero
}

/// A straight band of width `w` at `angle` through a 200 x 200 image.
Frame band(double w, double angle) {
    Frame f(200, 200);
    const double nx = -std::sin(angle), ny = std::cos(angle);
    for (int y = 0; y < 200; ++y)
        for (int x = 0; x < 200; ++x)
            if (std::abs((x + 0.5 - 100) * nx + (y + 0.5 - 100) * ny) < 0.5 * w) f.set(x, y, 1, flag_border);
    return f;
}

TEST(ImageMetrics, LineWidthOfAStraightBandIsItsWidthAtAnyAngle) {
    // Rasterised bands of width w at any angle: runs along the nearest of 4 directions are w up to
    // 1/cos(22.5 deg) = 1.082 longer, plus up to one pixel of rasterisation, so mean within
    // [w - 1, 1.082 w + 1].
    for (double w : {2.0, 4.0, 6.0})
        for (double degrees : {0.0, 10.0, 30.0, 45.0, 70.0, 90.0}) {
            const LineWidth width = line_width(band(w, degrees * M_PI / 180).ids(), flag_border);
            EXPECT_GE(width.mean, w - 1) << w << " at " << degrees;
            EXPECT_LE(width.mean, 1.082 * w + 1) << w << " at " << degrees;
        }
}

TEST(ImageMetrics, ErraticBandsHaveALargerSpread) {
    Frame steady = band(3, 0.3);
    Frame erratic(200, 200);
    for (int x = 0; x < 200; ++x) {
        const int w = 1 + (x * 7919) % 9;  // thickness jumping between 1 and 9 pixels
        for (int y = 100; y < 100 + w; ++y) erratic.set(x, y, 1, flag_border);
    }
    EXPECT_LT(line_width(steady.ids(), flag_border).stddev, line_width(erratic.ids(), flag_border).stddev);
}

}  // namespace
}  // namespace cutaway::metrics

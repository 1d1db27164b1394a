#include "metrics/image_metrics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cutaway::metrics {
namespace {

void require_same_size(const PixelIds& a, const PixelIds& b) {
    if (a.width != b.width || a.height != b.height || a.cell.size() != b.cell.size())
        throw std::invalid_argument("image metrics: frames of different sizes");
}

}  // namespace

Exposure primary_exposure(const PixelIds& primaries_only, const PixelIds& cutaway) {
    require_same_size(primaries_only, cutaway);
    Exposure exposure;
    for (std::size_t i = 0; i < primaries_only.cell.size(); ++i) {
        if (primaries_only.cell[i] == 0 || !(primaries_only.flags[i] & flag_primary)) continue;
        ++exposure.primary_pixels;
        if (cutaway.cell[i] == primaries_only.cell[i] && (cutaway.flags[i] & flag_primary)) ++exposure.visible;
    }
    exposure.fraction = exposure.primary_pixels == 0 ? 1.0 : double(exposure.visible) / double(exposure.primary_pixels);
    return exposure;
}

std::size_t context_pixels(const PixelIds& frame) {
    std::size_t count = 0;
    for (std::size_t i = 0; i < frame.cell.size(); ++i)
        if (frame.cell[i] != 0 && !(frame.flags[i] & (flag_primary | flag_cut_fill | flag_border))) ++count;
    return count;
}

std::size_t model_pixels(const PixelIds& frame) {
    return std::size_t(std::count_if(frame.cell.begin(), frame.cell.end(), [](std::uint32_t cell) { return cell != 0; }));
}

ContextShare context_share(const PixelIds& frame) {
    ContextShare share{0, context_pixels(frame), model_pixels(frame)};
    if (share.model > 0) share.fraction = double(share.context) / double(share.model);
    return share;
}

ContextKept context_kept(std::size_t kept, std::size_t kept_180, std::size_t uncut) {
    ContextKept result{1, kept, kept_180, uncut};
    if (uncut > kept_180)
        result.fraction = std::clamp((double(kept) - double(kept_180)) / double(uncut - kept_180), 0.0, 1.0);
    return result;
}

LineWidth line_width(const PixelIds& frame, std::uint32_t mask) {
    const int w = frame.width, h = frame.height;
    auto flagged = [&](int x, int y) {
        return x >= 0 && y >= 0 && x < w && y < h && (frame.flags[std::size_t(y) * std::size_t(w) + std::size_t(x)] & mask);
    };
    auto run = [&](int x, int y, int dx, int dy) {
        int n = 1;
        for (int k = 1; flagged(x + k * dx, y + k * dy); ++k) ++n;
        for (int k = 1; flagged(x - k * dx, y - k * dy); ++k) ++n;
        return n;
    };
    double sum = 0, sum_squares = 0;
    std::size_t count = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (!flagged(x, y)) continue;
            const double diagonal = std::sqrt(2.0) * std::min(run(x, y, 1, 1), run(x, y, 1, -1));
            const double width = std::min({double(run(x, y, 1, 0)), double(run(x, y, 0, 1)), diagonal});
            sum += width;
            sum_squares += width * width;
            ++count;
        }
    LineWidth result;
    result.pixels = count;
    if (count > 0) {
        result.mean = sum / double(count);
        result.stddev = std::sqrt(std::max(0.0, sum_squares / double(count) - result.mean * result.mean));
    }
    return result;
}

}  // namespace cutaway::metrics

#include "cone_field/chamfer.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "cone_field/cone_slope.h"

namespace cutaway::cone_field {
namespace {

/// One raster pass over a width x height image of heights (double, so that rounding does not add
/// up along long paths). direction +1: top-to-bottom, left-to-right, neighbours at p - step;
/// direction -1: the reverse order, neighbours at p + step.
void propagate_pass(std::vector<double>& heights, int width, int height, const std::vector<ChamferStep>& steps,
                    double slope, int direction) {
    const int first_y = direction > 0 ? 0 : height - 1;
    const int first_x = direction > 0 ? 0 : width - 1;
    for (int row = 0, y = first_y; row < height; ++row, y += direction) {
        for (int column = 0, x = first_x; column < width; ++column, x += direction) {
            double& here = heights[std::size_t(y) * std::size_t(width) + std::size_t(x)];
            for (const ChamferStep& step : steps) {
                const int nx = x - direction * step.dx;
                const int ny = y - direction * step.dy;
                if (nx < 0 || nx >= width || ny < 0 || ny >= height) continue;
                const double from_neighbour =
                    heights[std::size_t(ny) * std::size_t(width) + std::size_t(nx)] - slope * step.length;
                here = std::max(here, from_neighbour);
            }
        }
    }
}

}  // namespace

std::string_view chamfer_mask_name(ChamferMask mask) {
    switch (mask) {
    case ChamferMask::city_diagonal_3x3: return "chamfer_3x3_1_sqrt2";
    case ChamferMask::borgefors_3x3: return "chamfer_3x3_3_4";
    case ChamferMask::borgefors_5x5: return "chamfer_5x5_5_7_11";
    case ChamferMask::chessboard_3x3: return "chessboard_3x3_1_1";
    }
    throw std::invalid_argument("unknown chamfer mask");
}

std::vector<ChamferStep> chamfer_forward_steps(ChamferMask mask) {
    double edge = 1.0;
    double diagonal = 0.0;
    double knight = 0.0;  // 0: a 3x3 mask
    switch (mask) {
    case ChamferMask::city_diagonal_3x3: diagonal = std::sqrt(2.0); break;
    case ChamferMask::borgefors_3x3: diagonal = 4.0 / 3.0; break;
    case ChamferMask::borgefors_5x5:
        diagonal = 7.0 / 5.0;
        knight = 11.0 / 5.0;
        break;
    case ChamferMask::chessboard_3x3: diagonal = 1.0; break;
    default: throw std::invalid_argument("unknown chamfer mask");
    }
    std::vector<ChamferStep> steps{{1, 0, edge}, {1, 1, diagonal}, {0, 1, edge}, {-1, 1, diagonal}};
    if (knight > 0.0) {
        steps.insert(steps.end(), {{2, 1, knight}, {1, 2, knight}, {-1, 2, knight}, {-2, 1, knight}});
    }
    return steps;
}

FloatImage chamfer_cut(const SeedImage& seeds, double slope_per_pixel, ChamferMask mask) {
    check_slope_per_pixel(slope_per_pixel);
    check_seed_image(seeds);
    const std::vector<ChamferStep> steps = chamfer_forward_steps(mask);
    std::vector<double> heights(seeds.depth.pixels.size());
    std::transform(seeds.depth.pixels.begin(), seeds.depth.pixels.end(), heights.begin(),
                   [](float depth) { return std::max(0.0, double(depth)); });  // no_seed -> 0: the clamp
    propagate_pass(heights, seeds.width(), seeds.height(), steps, slope_per_pixel, +1);
    propagate_pass(heights, seeds.width(), seeds.height(), steps, slope_per_pixel, -1);
    FloatImage cut(seeds.width(), seeds.height());
    std::transform(heights.begin(), heights.end(), cut.pixels.begin(), [](double h) { return float(h); });
    return cut;
}

}  // namespace cutaway::cone_field

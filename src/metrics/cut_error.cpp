#include "metrics/cut_error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace cutaway::metrics {
namespace {

void check_inputs(const cone_field::FloatImage& cut, const cone_field::FloatImage& exact,
                  const CutErrorOptions& options, std::span<const std::uint8_t> compare_mask) {
    cone_field::check_image(cut, "cut image");
    cone_field::check_image(exact, "exact cut image");
    if (cut.width != exact.width || cut.height != exact.height) {
        throw std::invalid_argument("cut error: cut is " + std::to_string(cut.width) + " x " +
                                    std::to_string(cut.height) + " but the exact cut is " +
                                    std::to_string(exact.width) + " x " + std::to_string(exact.height));
    }
    if (!compare_mask.empty() && compare_mask.size() != cut.pixel_count()) {
        throw std::invalid_argument("cut error: mask holds " + std::to_string(compare_mask.size()) +
                                    " values for " + std::to_string(cut.pixel_count()) + " pixels");
    }
    if (!(options.relative_tolerance >= 0.0 && std::isfinite(options.relative_tolerance))) {
        throw std::invalid_argument("cut error: relative tolerance must be finite and >= 0, got " +
                                    std::to_string(options.relative_tolerance));
    }
}

/// The depth scale the relative tolerance multiplies (see CutErrorOptions).
double depth_scale(const cone_field::FloatImage& exact, std::span<const std::uint8_t> compare_mask) {
    double low = std::numeric_limits<double>::infinity();
    double high = -low;
    for (std::size_t i = 0; i < exact.pixel_count(); ++i) {
        if (!compare_mask.empty() && compare_mask[i] == 0) continue;
        low = std::min(low, double(exact.pixels[i]));
        high = std::max(high, double(exact.pixels[i]));
    }
    if (!(high >= low)) return 1.0;  // nothing compared
    if (high > low) return high - low;
    return std::abs(high) > 0.0 ? std::abs(high) : 1.0;
}

}  // namespace

CutError compare_cut(const cone_field::FloatImage& cut, const cone_field::FloatImage& exact,
                     const CutErrorOptions& options, std::span<const std::uint8_t> compare_mask) {
    check_inputs(cut, exact, options, compare_mask);
    CutError error;
    error.tolerance = options.relative_tolerance * depth_scale(exact, compare_mask);
    error.max_signed_error = -std::numeric_limits<double>::infinity();
    error.min_signed_error = std::numeric_limits<double>::infinity();
    double abs_error_sum = 0.0;
    for (std::size_t i = 0; i < cut.pixel_count(); ++i) {
        if (!compare_mask.empty() && compare_mask[i] == 0) continue;
        const double difference = double(cut.pixels[i]) - double(exact.pixels[i]);
        if (std::isnan(difference)) throw std::invalid_argument("cut error: pixel " + std::to_string(i) + " is NaN");
        ++error.pixels_compared;
        abs_error_sum += std::abs(difference);
        error.max_abs_error = std::max(error.max_abs_error, std::abs(difference));
        error.max_signed_error = std::max(error.max_signed_error, difference);
        error.min_signed_error = std::min(error.min_signed_error, difference);
        if (std::abs(difference) > error.tolerance) ++error.pixels_wrong;
    }
    if (error.pixels_compared == 0) {
        error.max_signed_error = error.min_signed_error = 0.0;
        return error;
    }
    error.mean_abs_error = abs_error_sum / double(error.pixels_compared);
    error.wrong_fraction = double(error.pixels_wrong) / double(error.pixels_compared);
    return error;
}

}  // namespace cutaway::metrics

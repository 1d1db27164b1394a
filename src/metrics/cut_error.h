#pragma once
// How far a cut surface lies from the exact one (SPEC section 2, "Alternative cut surfaces";
// stats.json `cut_vs_exact`). Pure CPU, images in CPU memory.
#include <cstddef>
#include <cstdint>
#include <span>

#include "cone_field/cone_image.h"

namespace cutaway::metrics {

struct CutErrorOptions {
    /// A pixel is wrong when |cut - exact| exceeds relative_tolerance * the exact cut's depth range
    /// (max - min over the compared pixels; max |exact| if that range is 0, 1 if both are 0).
    /// Default 1e-3: float32 arithmetic (CPU or GPU, a few dozen operations) differs from the
    /// double exact cut by ~1e-6 of the range, so rounding never counts as wrong, while picking a
    /// wrong seed or a wrong chamfer path typically costs a good part of a depth step m and does.
    double relative_tolerance = 1e-3;
};

struct CutError {
    std::size_t pixels_compared = 0;
    std::size_t pixels_wrong = 0;    ///< |cut - exact| > tolerance
    double wrong_fraction = 0.0;     ///< pixels_wrong / pixels_compared (0 when none compared)
    double tolerance = 0.0;          ///< the absolute tolerance used, depth units
    double mean_abs_error = 0.0;     ///< depth units
    double max_abs_error = 0.0;      ///< depth units
    double max_signed_error = 0.0;   ///< largest cut - exact: <= 0 when the cut is never above exact
    double min_signed_error = 0.0;   ///< smallest cut - exact: the deepest shortfall when negative
};

/// Compares `cut` against `exact` pixel by pixel. compare_mask: empty = every pixel, otherwise one
/// byte per pixel in the images' layout, nonzero = compare. Throws std::invalid_argument for
/// malformed images, mismatched sizes, a mask of the wrong size, a negative or NaN tolerance or a
/// NaN pixel.
CutError compare_cut(const cone_field::FloatImage& cut, const cone_field::FloatImage& exact,
                     const CutErrorOptions& options = {}, std::span<const std::uint8_t> compare_mask = {});

}  // namespace cutaway::metrics

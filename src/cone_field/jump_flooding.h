#pragma once
// Cone-field cut by jump flooding (Rong & Tan 2006), propagating which seed wins, not its value.
// Runs on the CPU as the reference for the GPU shader version: same step sequences (jfa_steps),
// same 9-tap rule, same tie-breaking, so the two can be compared pixel for pixel.
//
// Each pixel holds a seed (or none). A pass with step k reads the previous pass only: every pixel
// looks at the seeds held at its own position and at the 8 positions (+-k, 0, +-k) away, and keeps
// the one whose cone z(q) - m |q - p| is highest there (the one it holds on a tie, then the first
// in row-major tap order). The cut is that seed's cone height, clamped at 0. Because it is the
// height of a real seed's cone, the error is one-sided: never above the exact cut.
#include <array>
#include <span>
#include <string_view>
#include <vector>

#include "cone_field/cone_image.h"

namespace cutaway::cone_field {

enum class JfaVariant {
    jfa,           ///< steps N/2, N/4, ..., 1 with N = max(width, height) rounded up to a power of two
    jfa_plus_1,    ///< JFA, then one more pass with step 1
    jfa_plus_2,    ///< JFA, then passes with steps 2 and 1
    one_plus_jfa,  ///< a pass with step 1, then JFA
    jfa_squared,   ///< JFA twice
};

inline constexpr std::array<JfaVariant, 5> all_jfa_variants{JfaVariant::jfa, JfaVariant::jfa_plus_1,
                                                            JfaVariant::jfa_plus_2, JfaVariant::one_plus_jfa,
                                                            JfaVariant::jfa_squared};

/// "JFA", "JFA+1", "JFA+2", "1+JFA", "JFA^2".
std::string_view jfa_variant_name(JfaVariant variant);

/// The step sizes, pixels, of the passes of `variant` on a width x height image, in pass order.
/// Plain JFA on 512 x 512: 256, 128, ..., 1 (9 passes); on 1920 x 1080: 1024, ..., 1 (11 passes).
/// Throws std::invalid_argument for sizes check_image_size refuses.
std::vector<int> jfa_steps(JfaVariant variant, int width, int height);

/// The cut surface by jump flooding with the passes of `variant`; m = slope_per_pixel (depth units
/// per pixel). Output: the seed image's size, depth units, 0 where no cone reaches. Throws
/// std::invalid_argument for a malformed seed image or a slope that is not positive.
FloatImage jump_flooding_cut(const SeedImage& seeds, double slope_per_pixel, JfaVariant variant);

/// The same with any step sequence (each step >= 1 pixel), for experiments with new variants.
FloatImage jump_flooding_cut(const SeedImage& seeds, double slope_per_pixel, std::span<const int> steps);

}  // namespace cutaway::cone_field

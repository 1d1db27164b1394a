#include "cone_field/cone_slope.h"

#include <numbers>
#include <stdexcept>
#include <string>

namespace cutaway::cone_field {

double cone_slope_per_pixel(double theta_radians, double reference_depth, double focal_length_px) {
    if (!(theta_radians > 0.0 && theta_radians < std::numbers::pi / 2)) {
        throw std::invalid_argument("cone aperture theta must lie in (0, pi/2) radians, got " +
                                    std::to_string(theta_radians));
    }
    if (!(reference_depth > 0.0 && std::isfinite(reference_depth))) {
        throw std::invalid_argument("cone reference depth must be positive and finite, got " +
                                    std::to_string(reference_depth));
    }
    if (!(focal_length_px > 0.0 && std::isfinite(focal_length_px))) {
        throw std::invalid_argument("focal length must be positive and finite pixels, got " +
                                    std::to_string(focal_length_px));
    }
    const double slope = reference_depth / (std::tan(theta_radians) * focal_length_px);
    check_slope_per_pixel(slope);
    return slope;
}

void check_slope_per_pixel(double slope_per_pixel) {
    if (!(slope_per_pixel > 0.0 && std::isfinite(slope_per_pixel))) {
        throw std::invalid_argument("cone slope m must be positive and finite (depth units per pixel), got " +
                                    std::to_string(slope_per_pixel));
    }
}

}  // namespace cutaway::cone_field

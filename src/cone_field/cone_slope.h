#pragma once
// The cone every seed carries: its slope m (depth units per pixel) and its height at a pixel.
//
// The cut surface is d(p) = max(0, max over seeds q of (z(q) - m * |q - p|)), |q - p| in pixels:
// the rear hull of the union of cones with apex at each seed, opening towards the camera.
#include <cmath>
#include <cstdint>

namespace cutaway::cone_field {

/// Slope m of the screen-space cone of half-aperture `theta_radians` (angle between the cone's
/// wall and the view ray, 0 < theta < pi/2), in depth units per pixel.
///
/// A wall at angle theta to the view ray moves sideways by tan(theta) eye units per eye unit of
/// depth. At depth s one pixel spans s / focal_length_px eye units, so crossing one pixel sideways
/// changes the wall's depth by (s / focal_length_px) / tan(theta):
///     m = reference_depth / (tan(theta) * focal_length_px).
/// Under perspective the pixel footprint grows with depth; evaluating it at one reference_depth
/// (e.g. the primaries' mean depth, eye units) makes the cone straight in screen space.
/// focal_length_px = (height_px / 2) / tan(vertical_fov / 2). theta -> pi/2 is the 180-degree
/// aperture (m -> 0, everything in front of the farthest seed removed): handle it without cones.
/// Throws std::invalid_argument for theta outside (0, pi/2) or non-positive depth or focal length.
double cone_slope_per_pixel(double theta_radians, double reference_depth, double focal_length_px);

/// Throws std::invalid_argument unless 0 < slope_per_pixel < infinity (refuses NaN).
void check_slope_per_pixel(double slope_per_pixel);

/// Height z - m * sqrt(dx^2 + dy^2) of the cone of seed depth `seed_depth` at integer offset
/// (dx, dy) pixels from its apex. Every CPU strategy evaluates a seed through this one function,
/// in double precision, so exact results agree to the bit; it never increases with distance,
/// which the exact reference's pruning relies on.
inline double cone_height(double seed_depth, double slope_per_pixel, std::int64_t dx, std::int64_t dy) {
    const double distance = std::sqrt(double(dx) * double(dx) + double(dy) * double(dy));
    return seed_depth - slope_per_pixel * distance;
}

}  // namespace cutaway::cone_field

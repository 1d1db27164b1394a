#include "cutaway/temporal/cut_opening.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace cutaway::temporal {

CutOpening::CutOpening(std::size_t frames_to_open) : frames_to_open_(frames_to_open) {
    if (frames_to_open_ == 0) throw std::invalid_argument("cut opening: expected at least 1 frame to open, found 0");
}

float CutOpening::next(std::size_t primary_cells) {
    if (std::exchange(first_frame_, false) && primary_cells > 0) frames_open_ = frames_to_open_;
    if (primary_cells == 0) {
        frames_open_ = 0;
        return 0.0f;
    }
    ++frames_open_;
    return float(std::min(frames_open_ - 1, frames_to_open_)) / float(frames_to_open_);
}

float opened_aperture_deg(float full_deg, float opening) {
    const float t = std::clamp(opening, 0.0f, 1.0f);
    const float start_deg = 0.5f * full_deg;
    constexpr float flat_deg = 179.0f;  // tan(89.5 degrees) ~ 115: beyond it the area law means nothing
    if (full_deg >= flat_deg) return start_deg + t * (full_deg - start_deg);
    const auto half_tan_squared = [](float deg) {
        const double tan_half = std::tan(double(deg) * M_PI / 360.0);
        return tan_half * tan_half;
    };
    const double from = half_tan_squared(start_deg), to = half_tan_squared(full_deg);
    return float(360.0 / M_PI * std::atan(std::sqrt(from + double(t) * (to - from))));
}

}  // namespace cutaway::temporal

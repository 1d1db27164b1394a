#include "annotation/axis_ticks.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace cutaway::annotation {

namespace {

/// `value` printed with the digits that step `step` needs: 0.05 -> 2 decimals, 2.5 -> 1, 500 -> 0;
/// %g beyond 1e6 or below 1e-4 (values of that size print shorter with an exponent).
std::string tick_label(double value, double step) {
    char text[48];
    const double magnitude = std::max(std::abs(value), step);
    if (magnitude >= 1e6 || step < 1e-4) {
        std::snprintf(text, sizeof text, "%.3g", value);
    } else {
        int decimals = 0;
        while (decimals < 8 && std::abs(step * std::pow(10.0, decimals) - std::round(step * std::pow(10.0, decimals))) >
                                   1e-6 * step * std::pow(10.0, decimals))
            ++decimals;
        std::snprintf(text, sizeof text, "%.*f", decimals, value);
    }
    std::string label = text;
    if (label.front() == '-' && label.find_first_not_of("-0.") == std::string::npos)
        label.erase(0, 1);  // no "-0.00" for a tick at zero
    return label;
}

}  // namespace

AxisTicks nice_ticks(double lo, double hi, int min_count) {
    if (!std::isfinite(lo) || !std::isfinite(hi) || lo > hi || min_count < 1)
        throw std::invalid_argument("axis ticks: expected a finite range lo <= hi and a count >= 1");
    AxisTicks ticks;
    if (lo == hi) {
        ticks.values = {lo};
        ticks.labels = {tick_label(lo, std::max(std::abs(lo), 1e-12))};
        return ticks;
    }
    // Steps from large to small: the first with min_count ticks inside [lo, hi] wins.
    static constexpr std::array<double, 4> mantissas{5, 2.5, 2, 1};
    const double exponent = std::floor(std::log10(hi - lo));
    double power = std::pow(10.0, exponent);
    for (int decade = 0; decade < 12; ++decade, power /= 10) {
        for (const double mantissa : mantissas) {
            const double step = mantissa * power;
            const double first = std::ceil(lo / step - 1e-9), last = std::floor(hi / step + 1e-9);
            if (last - first + 1 < min_count) continue;
            for (double k = first; k <= last; ++k) {
                const double value = std::clamp(k * step, lo, hi);  // lo/hi themselves when within rounding
                ticks.values.push_back(value);
                ticks.labels.push_back(tick_label(k * step, step));
            }
            return ticks;
        }
    }
    // A range too narrow for its magnitude in double precision: evenly spaced values instead.
    for (int k = 0; k < min_count; ++k) {
        const double value = lo + (hi - lo) * k / std::max(1, min_count - 1);
        char text[48];
        std::snprintf(text, sizeof text, "%.9g", value);
        ticks.values.push_back(value);
        ticks.labels.push_back(text);
    }
    return ticks;
}

}  // namespace cutaway::annotation

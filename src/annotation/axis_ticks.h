#pragma once
// Tick values a reader can read: round numbers (1, 2, 2.5 or 5 times a power of ten) inside a range.
#include <string>
#include <vector>

namespace cutaway::annotation {

struct AxisTicks {
    std::vector<double> values;  ///< ascending, inside [lo, hi]
    std::vector<std::string> labels;  ///< one per value, as few digits as the step needs
};

/// At least `min_count` round ticks inside [lo, hi] (lo < hi, both finite), at most about
/// 2 * min_count + 1; for lo == hi the single value. Throws std::invalid_argument otherwise.
AxisTicks nice_ticks(double lo, double hi, int min_count = 3);

}  // namespace cutaway::annotation

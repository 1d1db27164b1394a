#pragma once
// The median every report quotes (stage times over repeated frames, benchmark rounds): the middle
// value, or the mean of the two middle values of an even count; 0 for no values.
#include <algorithm>
#include <cstddef>
#include <iterator>
#include <vector>

namespace cutaway::metrics {

inline double median(std::vector<double> values) {
    if (values.empty()) return 0;
    const std::size_t middle = values.size() / 2;
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(middle), values.end());
    const double upper = values[middle];
    if (values.size() % 2 == 1) return upper;
    // After nth_element everything before `middle` is <= upper; the largest of them is the lower middle.
    return 0.5 * (*std::max_element(values.begin(), values.begin() + std::ptrdiff_t(middle)) + upper);
}

}  // namespace cutaway::metrics

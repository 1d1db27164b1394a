#include "viewer/rolling_median.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace cutaway::viewer {

RollingMedian::RollingMedian(std::size_t window) : window_(window) {
    if (window == 0) throw std::invalid_argument("rolling median window 0; expected at least 1 value");
}

void RollingMedian::add(double value) {
    if (!std::isfinite(value)) return;
    if (values_.size() == window_) values_.pop_front();
    values_.push_back(value);
}

double RollingMedian::median() const {
    if (values_.empty()) return 0;
    std::vector<double> sorted(values_.begin(), values_.end());
    const std::size_t middle = sorted.size() / 2;
    std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(middle), sorted.end());
    const double upper = sorted[middle];
    if (sorted.size() % 2 == 1) return upper;
    // After nth_element everything before `middle` is <= upper; the largest of them is the lower middle.
    const double lower = *std::max_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(middle));
    return 0.5 * (lower + upper);
}

std::size_t RollingMedian::size() const { return values_.size(); }

void RollingMedian::clear() { values_.clear(); }

}  // namespace cutaway::viewer

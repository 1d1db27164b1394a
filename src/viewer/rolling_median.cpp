#include "viewer/rolling_median.h"

#include <cmath>
#include <stdexcept>
#include <vector>

#include "metrics/median.h"

namespace cutaway::viewer {

RollingMedian::RollingMedian(std::size_t window) : window_(window) {
    if (window == 0) throw std::invalid_argument("rolling median window 0; expected at least 1 value");
}

void RollingMedian::add(double value) {
    if (!std::isfinite(value)) return;
    if (values_.size() == window_) values_.pop_front();
    values_.push_back(value);
}

double RollingMedian::median() const { return metrics::median({values_.begin(), values_.end()}); }

std::size_t RollingMedian::size() const { return values_.size(); }

void RollingMedian::clear() { values_.clear(); }

}  // namespace cutaway::viewer

#pragma once
// Median of the most recent values: steady per-stage timings for the viewer's overlay (a median
// ignores the odd slow frame that a mean would smear over the whole window).
#include <cstddef>
#include <deque>

namespace cutaway::viewer {

class RollingMedian {
public:
    /// Keeps the last `window` values; `window` 0 throws std::invalid_argument.
    explicit RollingMedian(std::size_t window = 31);

    /// Adds a value, dropping the oldest when the window is full. NaN and infinities are ignored.
    void add(double value);
    /// Median of the values held: 0 when empty, the mean of the two middle values for even counts.
    double median() const;
    /// Values held (at most the window).
    std::size_t size() const;
    void clear();

private:
    std::size_t window_;
    std::deque<double> values_;  ///< oldest first
};

}  // namespace cutaway::viewer

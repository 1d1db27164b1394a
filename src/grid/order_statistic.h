#pragma once
// The exact k-th smallest of a stream of floats without holding the stream: a two-pass radix
// select on the floats' order-preserving 32-bit keys (high 16 bits, then low 16 bits of the
// candidates). The value equals what std::nth_element finds at position k of the whole array.
// Each pass's histogram may be summed across processes before the pass is finished, so the
// stream may be split over several (distributed/ does this with MPI).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace cutaway::grid {

class OrderStatistic {
public:
    /// `position`: 0-based, in ascending order, below the stream's length.
    explicit OrderStatistic(std::size_t position);

    /// Every value of the stream, once per pass, in any order (no NaN).
    void add(float value) {
        const std::uint32_t key = key_of(value);
        if (pass_ == 0) ++counts_[key >> 16];
        else if ((key >> 16) == high_) ++counts_[key & 0xFFFFu];
    }
    /// This pass's histogram (65536 counts).
    std::vector<std::uint64_t>& counts() { return counts_; }
    /// Ends a pass; true while another pass over the same stream is needed.
    bool finish_pass();
    float value() const;

    /// The order-preserving key of a float (negative values reversed below the positive ones).
    static std::uint32_t key_of(float value) {
        std::uint32_t bits = 0;
        std::memcpy(&bits, &value, sizeof bits);
        return bits & 0x80000000u ? ~bits : bits | 0x80000000u;
    }

private:
    std::size_t position_;
    int pass_ = 0;
    std::uint32_t high_ = 0, low_ = 0;
    std::vector<std::uint64_t> counts_;
};

/// quantile(values, fraction) of generators/smooth_field.h for a stream: the value at position
/// min(n - 1, floor(fraction * n)); `for_each(sink)` calls sink(value) for each of the `count`
/// values (twice over). 0 for an empty stream.
template <typename ForEach>
float streamed_quantile(std::size_t count, double fraction, ForEach&& for_each) {
    if (count == 0) return 0;
    OrderStatistic select(std::min(count - 1, std::size_t(fraction * double(count))));
    do for_each([&select](float value) { select.add(value); });
    while (select.finish_pass());
    return select.value();
}

}  // namespace cutaway::grid

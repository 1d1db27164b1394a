#include "grid/order_statistic.h"

#include <cstring>
#include <stdexcept>

namespace cutaway::grid {
namespace {

/// The bin of `counts` holding position `*position` (counted from the first bin); `*position`
/// becomes the position within that bin.
std::uint32_t bin_of(const std::vector<std::uint64_t>& counts, std::size_t* position) {
    for (std::uint32_t bin = 0; bin < counts.size(); ++bin) {
        if (*position < counts[bin]) return bin;
        *position -= counts[bin];
    }
    throw std::logic_error("OrderStatistic: the position lies beyond the stream");
}

}  // namespace

OrderStatistic::OrderStatistic(std::size_t position) : position_(position), counts_(std::size_t(1) << 16, 0) {}

bool OrderStatistic::finish_pass() {
    if (pass_ == 0) {
        high_ = bin_of(counts_, &position_);
        counts_.assign(counts_.size(), 0);
        pass_ = 1;
        return true;
    }
    low_ = bin_of(counts_, &position_);
    pass_ = 2;
    return false;
}

float OrderStatistic::value() const {
    if (pass_ != 2) throw std::logic_error("OrderStatistic: value() before both passes");
    const std::uint32_t key = high_ << 16 | low_;
    const std::uint32_t bits = key & 0x80000000u ? key & 0x7FFFFFFFu : ~key;
    float value = 0;
    std::memcpy(&value, &bits, sizeof value);
    return value;
}

}  // namespace cutaway::grid

#include "cutaway/quantised_values.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cutaway::pipeline {

QuantisedValues quantise_unorm16(std::span<const float> values) {
    float low = std::numeric_limits<float>::infinity();
    float high = -low;
    for (const float v : values) {
        if (!std::isfinite(v)) continue;
        low = std::min(low, v);
        high = std::max(high, v);
    }
    QuantisedValues q;
    q.codes.resize(values.size(), 0);
    if (low > high) return q;  // no finite value
    q.offset = low;
    q.span = high - low;
    const double span = double(high) - double(low);
    if (span <= 0) return q;
    for (std::size_t c = 0; c < values.size(); ++c)
        if (std::isfinite(values[c]))
            q.codes[c] = std::uint16_t(std::lround((double(values[c]) - double(low)) / span * 65535.0));
    return q;
}

}  // namespace cutaway::pipeline

#include "volume/level_window.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <stdexcept>

namespace cutaway::volume {

LevelWindow percentile_window(const QuantisedVolume& volume, double lo_fraction, double hi_fraction) {
    if (!(lo_fraction >= 0 && lo_fraction < hi_fraction && hi_fraction <= 1))
        throw std::invalid_argument("level window: expected 0 <= lo fraction < hi fraction <= 1");
    if (volume.levels.empty()) return {};
    std::array<std::size_t, 256> histogram{};
    for (const std::uint8_t level : volume.levels) ++histogram[level];
    const double count = double(volume.levels.size());
    const auto quantile = [&](double fraction) {
        std::size_t below = 0;
        for (int level = 0; level < 256; ++level) {
            below += histogram[std::size_t(level)];
            if (double(below) >= fraction * count) return double(level);
        }
        return 255.0;
    };
    LevelWindow window{quantile(lo_fraction), quantile(hi_fraction)};
    if (window.hi - window.lo < 2) {  // widen about the middle, inside 0..255
        const double middle = std::clamp(0.5 * (window.lo + window.hi), 1.0, 254.0);
        window = {middle - 1, middle + 1};
    }
    return window;
}

LayerHighlight fitted_layer(const LevelWindow& window) {
    return {1.0, std::max(1.0, 0.5 * (window.hi - window.lo)), 1.0, window.hi};
}

double level_value(double level, ValueRange range) {
    return double(range.min) + level / 255.0 * (double(range.max) - double(range.min));
}

}  // namespace cutaway::volume

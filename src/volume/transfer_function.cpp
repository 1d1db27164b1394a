#include "volume/transfer_function.h"

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <stdexcept>

namespace cutaway::volume {

TransferFunctionKind parse_transfer_function(const std::string& name) {
    if (name == "grey" || name == "gray") return TransferFunctionKind::grey;
    if (name == "pseudo") return TransferFunctionKind::pseudo;
    if (name == "layer") return TransferFunctionKind::layer;
    throw std::invalid_argument("transfer function '" + name + "': expected grey, pseudo or layer");
}

const char* transfer_function_name(TransferFunctionKind kind) {
    switch (kind) {
        case TransferFunctionKind::grey: return "grey";
        case TransferFunctionKind::pseudo: return "pseudo";
        case TransferFunctionKind::layer: return "layer";
    }
    return "unknown";
}

Rgba perceptual_colour(double t) {
    static constexpr std::uint8_t viridis[256][3] = {
#include "annotation/viridis_table.inc"
    };
    const double x = std::clamp(t, 0.0, 1.0) * 255.0;
    const std::size_t i = std::min<std::size_t>(std::size_t(x), 254);
    const float f = float(x - double(i));
    Rgba c{0, 0, 0, 1};
    float* channel[3] = {&c.r, &c.g, &c.b};
    for (std::size_t k = 0; k < 3; ++k)
        *channel[k] = (float(viridis[i][k]) + f * (float(viridis[i + 1][k]) - float(viridis[i][k]))) / 255.0f;
    return c;
}

ColourScale parse_colour_scale(const std::string& name) {
    if (name == "perceptual") return ColourScale::perceptual;
    if (name == "rainbow") return ColourScale::rainbow;
    throw std::invalid_argument("colour scale '" + name + "': expected perceptual or rainbow");
}

const char* colour_scale_name(ColourScale scale) { return scale == ColourScale::rainbow ? "rainbow" : "perceptual"; }

double window_position(double level, const LevelWindow& window) {
    return std::clamp((level - window.lo) / (window.hi - window.lo), 0.0, 1.0);
}

Rgba pseudo_colour(double t) {
    constexpr std::array<Rgba, 4> stops{Rgba{0, 0, 1, 1}, Rgba{0, 1, 0, 1}, Rgba{1, 1, 0, 1}, Rgba{1, 0, 0, 1}};
    const double x = std::clamp(t, 0.0, 1.0) * 3.0;
    const std::size_t i = std::min<std::size_t>(std::size_t(x), 2);
    const float f = float(x - double(i));
    const Rgba& a = stops[i];
    const Rgba& b = stops[i + 1];
    return {a.r + f * (b.r - a.r), a.g + f * (b.g - a.g), a.b + f * (b.b - a.b), 1};
}

double layer_alpha(double level, const LayerHighlight& layer) {
    const double distance = std::abs(level - layer.f_v);
    if (distance > layer.r) return 0;
    return std::clamp(layer.alpha_v * (1 - layer.k * distance / layer.r), 0.0, 1.0);
}

TransferTable build_transfer_table(const TransferFunctionSettings& settings) {
    if (settings.opacity < 0 || settings.opacity > 1)
        throw std::invalid_argument("transfer function opacity " + std::to_string(settings.opacity) +
                                    ": expected 0..1");
    const LayerHighlight& layer = settings.layer;
    if (settings.kind == TransferFunctionKind::layer &&
        (!(layer.r > 0) || layer.alpha_v < 0 || layer.alpha_v > 1 || layer.k < 0))
        throw std::invalid_argument("layer highlight: r = " + std::to_string(layer.r) + ", alpha_v = " +
                                    std::to_string(layer.alpha_v) + ", k = " + std::to_string(layer.k) +
                                    "; expected r > 0, 0 <= alpha_v <= 1, k >= 0");
    if (!(settings.window.hi > settings.window.lo))
        throw std::invalid_argument("transfer function window [" + std::to_string(settings.window.lo) + ", " +
                                    std::to_string(settings.window.hi) + "]: expected lo < hi (levels)");
    TransferTable table;
    for (int level = 0; level < 256; ++level) {
        const double t = window_position(level, settings.window);
        Rgba entry;
        if (settings.kind == TransferFunctionKind::grey) {
            entry = {float(t), float(t), float(t), float(settings.opacity * t)};
        } else {
            entry = settings.scale == ColourScale::rainbow ? pseudo_colour(t) : perceptual_colour(t);
            entry.a = settings.kind == TransferFunctionKind::layer ? float(layer_alpha(level, layer))
                                                                   : float(settings.opacity * (2 * t - 1) * (2 * t - 1));
        }
        table[std::size_t(level)] = entry;
    }
    return table;
}

Rgba lookup(const TransferTable& table, float level) {
    const float x = std::clamp(level, 0.0f, 255.0f);
    const int i = std::min(int(x), 254);
    const float f = x - float(i);
    const Rgba& a = table[std::size_t(i)];
    const Rgba& b = table[std::size_t(i) + 1];
    return {a.r + f * (b.r - a.r), a.g + f * (b.g - a.g), a.b + f * (b.b - a.b), a.a + f * (b.a - a.a)};
}

}  // namespace cutaway::volume

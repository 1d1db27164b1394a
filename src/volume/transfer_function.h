#pragma once
// Transfer functions over the 256 levels: grey, pseudo-colour (blue -> green -> yellow -> red as the
// level rises) and the paper's layer highlight (eq. 1). Tables hold straight (not premultiplied)
// colour and the opacity of one voxel-length step.
#include <array>
#include <string>

namespace cutaway::volume {

enum class TransferFunctionKind { grey, pseudo, layer };

/// Eq. 1: alpha(p) = alpha_v (1 - k |f(p) - f_v| / r) where |f(p) - f_v| <= r, else 0; f in levels.
struct LayerHighlight {
    double k = 1;
    double r = 60;         ///< half-width of the highlighted band, levels (> 0)
    double alpha_v = 1;    ///< opacity at f_v, 0..1
    double f_v = 255;      ///< highlighted level (the paper: the maximum value)
};

struct TransferFunctionSettings {
    TransferFunctionKind kind = TransferFunctionKind::grey;
    /// grey and pseudo: opacity of level 255 per voxel step; level L gets opacity * L / 255.
    double opacity = 0.3;
    LayerHighlight layer;  ///< layer only (its colours are the pseudo-colour ramp)
};

struct Rgba {
    float r = 0, g = 0, b = 0, a = 0;
};

/// Entry L: colour and opacity of level L.
using TransferTable = std::array<Rgba, 256>;

/// "grey", "pseudo" or "layer"; throws std::invalid_argument naming the accepted names.
TransferFunctionKind parse_transfer_function(const std::string& name);
const char* transfer_function_name(TransferFunctionKind kind);

/// Pseudo-colour at `t` in [0, 1]: blue (0), green (1/3), yellow (2/3), red (1), linear between.
Rgba pseudo_colour(double t);

/// Eq. 1 at level `level`, clamped to [0, 1].
double layer_alpha(double level, const LayerHighlight& layer);

/// The 256-entry table; throws std::invalid_argument for r <= 0, or opacities outside [0, 1].
TransferTable build_transfer_table(const TransferFunctionSettings& settings);

/// The table at continuous level `level` in [0, 255]: linear between neighbouring entries (the
/// GLSL caster does the same with texelFetch, so both casters classify identically).
Rgba lookup(const TransferTable& table, float level);

}  // namespace cutaway::volume

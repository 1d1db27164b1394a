#pragma once
// Transfer functions over the 256 levels: grey, pseudo-colour (a perceptual map, viridis, or the
// paper's blue -> green -> yellow -> red) and the paper's layer highlight (eq. 1), each over a window
// of levels fitted to the data (the 2-98 percentile levels: seismic amplitudes crowd the middle of
// their range, so a table over all 256 levels shows one hue). Tables hold straight (not
// premultiplied) colour and the opacity of one voxel-length step.
#include <array>
#include <string>

namespace cutaway::volume {

enum class TransferFunctionKind { grey, pseudo, layer };

/// Colours of pseudo and layer: viridis (perceptually uniform, readable in grey) or the paper's rainbow.
enum class ColourScale { perceptual, rainbow };

/// The levels mapped to the two ends of the colour scale; levels outside clamp to the ends.
struct LevelWindow {
    double lo = 0;
    double hi = 255;  ///< > lo
};

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
    LevelWindow window;    ///< levels spanning the colour scale (and grey's opacity ramp)
    ColourScale scale = ColourScale::perceptual;
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
/// Viridis at `t` in [0, 1] (dark blue-violet, green, yellow), linear between its 256 entries.
Rgba perceptual_colour(double t);
ColourScale parse_colour_scale(const std::string& name);  ///< "perceptual" or "rainbow"
const char* colour_scale_name(ColourScale scale);
/// Position of `level` in `window`, clamped to [0, 1].
double window_position(double level, const LevelWindow& window);

/// Eq. 1 at level `level`, clamped to [0, 1].
double layer_alpha(double level, const LayerHighlight& layer);

/// The 256-entry table. grey: level L is grey window_position(L) with opacity * that position;
/// pseudo: the colour scale at the position, opacity * (2 position - 1)^2 (seismic amplitudes are
/// signed: troughs and peaks both show, the background near zero stays clear); layer: the colour
/// scale with eq. 1's opacity. Throws std::invalid_argument for r <= 0, opacities outside [0, 1]
/// or an empty window.
TransferTable build_transfer_table(const TransferFunctionSettings& settings);

/// The table at continuous level `level` in [0, 255]: linear between neighbouring entries (the
/// GLSL caster does the same with texelFetch, so both casters classify identically).
Rgba lookup(const TransferTable& table, float level);

}  // namespace cutaway::volume

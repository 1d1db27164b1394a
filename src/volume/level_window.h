#pragma once
// The levels a transfer function spans, fitted to the data: seismic amplitudes crowd the middle
// of their range (a few extreme samples set min and max), so a table over all 256 levels leaves
// most voxels one colour.
#include "volume/quantised_volume.h"
#include "volume/transfer_function.h"

namespace cutaway::volume {

/// Levels at the `lo_fraction` and `hi_fraction` quantiles of the volume's samples (default 2% and
/// 98%), at least 2 levels apart (a nearly constant cube keeps a usable window).
LevelWindow percentile_window(const QuantisedVolume& volume, double lo_fraction = 0.02, double hi_fraction = 0.98);

/// The paper's layer highlight (eq. 1) fitted to `window`: the band of the strongest amplitudes,
/// centred at the window's top, half as wide as the window, fully opaque at its centre.
LayerHighlight fitted_layer(const LevelWindow& window);

/// Sample value of (continuous) level `level`: the inverse of quantise_value.
double level_value(double level, ValueRange range);

}  // namespace cutaway::volume

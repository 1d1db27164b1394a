#pragma once
// Spatially correlated random fields with standard normal marginals, cheap enough for 10M cells:
// Gaussian values on a coarse lattice (spacing = correlation length) blended with smoothstep
// weights and renormalised so every point has unit variance.
#include <cstddef>
#include <vector>

#include "deterministic_random.h"

namespace cutaway::generators {

/// One correlated 2D field over [0, length_x] x [0, length_y] (metres).
class SmoothField2D {
public:
    SmoothField2D(DeterministicRandom& random, double length_x, double length_y, double correlation_length);
    /// Same lattice as `previous`, correlated with it by `rho` in [0, 1] (AR(1) between layers).
    SmoothField2D(const SmoothField2D& previous, double rho, DeterministicRandom& random);

    /// Standard normal value at (x, y) metres; points outside the extent clamp to its border.
    double at(double x, double y) const;

private:
    int nodes_x_ = 0;
    int nodes_y_ = 0;
    double spacing_ = 1;
    std::vector<double> nodes_;  ///< nodes_x_ * nodes_y_ Gaussian values, x fastest
};

/// A layered field on a regular lateral lattice: `count_x` x `count_y` points spaced `dx`, `dy`
/// metres, `layers` layers, layer-to-layer correlation `rho`. Returns count_x*count_y*layers
/// standard normal values, x fastest, then y, then layer.
std::vector<float> layered_field(int count_x, int count_y, int layers, double dx, double dy,
                                 double correlation_length, double rho, DeterministicRandom& random);

/// The value below which a share `fraction` of `values` lies (exact order statistic).
float quantile(std::vector<float> values, double fraction);

}  // namespace cutaway::generators

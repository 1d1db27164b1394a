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
/// metres, `layers` layers, layer-to-layer correlation `rho`. Holds only the layers' coarse
/// lattices (drawn in order from `random`), so any point is evaluated on demand: a block of the
/// field costs no more than the block.
class LayeredField {
public:
    LayeredField(int count_x, int count_y, int layers, double dx, double dy, double correlation_length, double rho,
                 DeterministicRandom& random);
    /// Standard normal value at lattice point (i, j) of layer k.
    float at(int i, int j, int k) const {
        return float(layers_[std::size_t(k)].at((i + 0.5) * dx_, (j + 0.5) * dy_));
    }
    int count_x() const { return count_x_; }
    int count_y() const { return count_y_; }
    int layers() const { return int(layers_.size()); }
    std::size_t size() const { return std::size_t(count_x_) * std::size_t(count_y_) * layers_.size(); }

private:
    int count_x_, count_y_;
    double dx_, dy_;
    std::vector<SmoothField2D> layers_;
};

/// The value below which a share `fraction` of `values` lies (exact order statistic).
float quantile(std::vector<float> values, double fraction);
/// quantile() of every value of `field`, without holding them.
float quantile(const LayeredField& field, double fraction);

}  // namespace cutaway::generators

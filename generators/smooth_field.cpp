#include "smooth_field.h"

#include <algorithm>
#include <cmath>

#include "grid/order_statistic.h"

namespace cutaway::generators {
namespace {

double smoothstep(double t) { return t * t * (3 - 2 * t); }

}  // namespace

SmoothField2D::SmoothField2D(DeterministicRandom& random, double length_x, double length_y,
                             double correlation_length)
    : nodes_x_(int(std::ceil(length_x / correlation_length)) + 2),
      nodes_y_(int(std::ceil(length_y / correlation_length)) + 2),
      spacing_(correlation_length),
      nodes_(std::size_t(nodes_x_) * std::size_t(nodes_y_)) {
    for (double& v : nodes_) v = random.normal();
}

SmoothField2D::SmoothField2D(const SmoothField2D& previous, double rho, DeterministicRandom& random)
    : nodes_x_(previous.nodes_x_), nodes_y_(previous.nodes_y_), spacing_(previous.spacing_), nodes_(previous.nodes_) {
    const double fresh = std::sqrt(std::max(0.0, 1 - rho * rho));
    for (double& v : nodes_) v = rho * v + fresh * random.normal();
}

double SmoothField2D::at(double x, double y) const {
    const double gx = std::clamp(x / spacing_, 0.0, double(nodes_x_ - 1) - 1e-9);
    const double gy = std::clamp(y / spacing_, 0.0, double(nodes_y_ - 1) - 1e-9);
    const int ix = int(gx), iy = int(gy);
    const double a = smoothstep(gx - ix), b = smoothstep(gy - iy);
    const std::size_t n00 = std::size_t(iy) * std::size_t(nodes_x_) + std::size_t(ix);
    const std::size_t n01 = n00 + std::size_t(nodes_x_);
    const double value = (1 - b) * ((1 - a) * nodes_[n00] + a * nodes_[n00 + 1]) +
                         b * ((1 - a) * nodes_[n01] + a * nodes_[n01 + 1]);
    // Independent unit nodes: the blend's variance is the sum of squared weights.
    const double norm = std::sqrt(((1 - a) * (1 - a) + a * a) * ((1 - b) * (1 - b) + b * b));
    return value / norm;
}

LayeredField::LayeredField(int count_x, int count_y, int layers, double dx, double dy, double correlation_length,
                           double rho, DeterministicRandom& random)
    : count_x_(count_x), count_y_(count_y), dx_(dx), dy_(dy) {
    layers_.reserve(std::size_t(layers));
    layers_.emplace_back(random, dx * count_x, dy * count_y, correlation_length);
    for (int k = 1; k < layers; ++k) layers_.emplace_back(layers_.back(), rho, random);
}

float quantile(std::vector<float> values, double fraction) {
    if (values.empty()) return 0;
    const auto rank = std::min(values.size() - 1, std::size_t(fraction * double(values.size())));
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(rank), values.end());
    return values[rank];
}

float quantile(const LayeredField& field, double fraction) {
    return grid::streamed_quantile(field.size(), fraction, [&field](const auto& sink) {
        for (int k = 0; k < field.layers(); ++k)
            for (int j = 0; j < field.count_y(); ++j)
                for (int i = 0; i < field.count_x(); ++i) sink(field.at(i, j, k));
    });
}

}  // namespace cutaway::generators

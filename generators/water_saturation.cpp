#include "water_saturation.h"

#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

#include "smooth_field.h"

namespace cutaway::generators {
namespace {

constexpr double kVerticalSpeedFactor = 0.1;  ///< kv/kh: the front spreads mostly along layers
constexpr double kLastStepSweep = 0.8;        ///< share of reachable cells swept at the last step

/// Injector columns at random; each needs an active cell somewhere in its column (falls back to
/// any column if the draws keep missing).
std::vector<grid::CellIjk> pick_injectors(const GeneratorParameters& p, const std::vector<std::uint8_t>& actnum,
                                          DeterministicRandom& random) {
    const grid::GridDims& d = p.dims;
    std::vector<grid::CellIjk> injectors;
    for (int n = 0; n < p.injector_count; ++n) {
        grid::CellIjk column{};
        for (int attempt = 0; attempt < 1000; ++attempt) {
            column = {int(random.below(std::uint64_t(d.nx))), int(random.below(std::uint64_t(d.ny))), 0};
            bool any_active = false;
            for (int k = 0; k < d.nz && !any_active; ++k) any_active = actnum[d.cell_index(column.i, column.j, k)] != 0;
            if (any_active) break;
        }
        injectors.push_back(column);
    }
    return injectors;
}

/// Travel time from the injectors to every active cell (infinity where unreachable), Dijkstra
/// over the six face neighbours; a step costs its length over sqrt of the geometric-mean permeability.
std::vector<float> arrival_times(const grid::GridDims& d, const grid::Point3& cell_size,
                                 const std::vector<grid::CellIjk>& injectors, const std::vector<std::uint8_t>& actnum,
                                 const std::vector<float>& permx) {
    std::vector<float> arrival(d.cell_count(), std::numeric_limits<float>::infinity());
    using Entry = std::pair<float, std::uint32_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
    for (const grid::CellIjk& column : injectors)
        for (int k = 0; k < d.nz; ++k) {
            const std::size_t cell = d.cell_index(column.i, column.j, k);
            if (actnum[cell] && arrival[cell] > 0) {
                arrival[cell] = 0;
                queue.emplace(0.0f, std::uint32_t(cell));
            }
        }
    const double speed_scale[3] = {1, 1, kVerticalSpeedFactor};
    const double length[3] = {cell_size.x, cell_size.y, cell_size.z};
    while (!queue.empty()) {
        const auto [time, cell] = queue.top();
        queue.pop();
        if (time > arrival[cell]) continue;
        const grid::CellIjk c = grid::cell_ijk(d, cell);
        for (int axis = 0; axis < 3; ++axis)
            for (int step : {-1, 1}) {
                grid::CellIjk n = c;
                (axis == 0 ? n.i : axis == 1 ? n.j : n.k) += step;
                if (!d.contains(n.i, n.j, n.k)) continue;
                const std::size_t next = d.cell_index(n.i, n.j, n.k);
                if (!actnum[next]) continue;
                const double speed = speed_scale[axis] * std::pow(double(permx[cell]) * double(permx[next]), 0.25);
                const float t = float(time + length[axis] / speed);
                if (t < arrival[next]) {
                    arrival[next] = t;
                    queue.emplace(t, std::uint32_t(next));
                }
            }
    }
    return arrival;
}

}  // namespace

WaterFlood make_water_flood(const GeneratorParameters& p, const ModelFrame& frame, double mean_layer_thickness,
                            const std::vector<std::uint8_t>& actnum, const std::vector<float>& permx,
                            DeterministicRandom& random) {
    WaterFlood flood;
    if (p.time_steps == 0) return flood;
    flood.injectors = pick_injectors(p, actnum, random);
    const std::vector<float> arrival =
        arrival_times(p.dims, {frame.dx, frame.dy, mean_layer_thickness}, flood.injectors, actnum, permx);

    std::vector<float> reached;
    std::size_t active = 0;
    for (std::size_t c = 0; c < arrival.size(); ++c) {
        active += actnum[c] != 0;
        if (std::isfinite(arrival[c])) reached.push_back(arrival[c]);
    }
    const double last_front = std::max(double(quantile(std::move(reached), kLastStepSweep)), 1e-30);
    for (int step = 1; step <= p.time_steps; ++step) {
        const double front_time = last_front * step / p.time_steps;
        std::vector<float> swat(arrival.size(), SaturationModel::connate);
        std::size_t swept = 0;
        for (std::size_t c = 0; c < arrival.size(); ++c) {
            if (!(arrival[c] <= front_time)) continue;
            const double behind = 1 - arrival[c] / front_time;  // 0 at the front, 1 at the injector
            swat[c] = float(SaturationModel::front +
                            (1 - SaturationModel::residual_oil - SaturationModel::front) * std::sqrt(behind));
            ++swept;
        }
        flood.swept_fraction.push_back(active ? double(swept) / double(active) : 0.0);
        flood.steps.push_back(std::move(swat));
    }
    return flood;
}

}  // namespace cutaway::generators

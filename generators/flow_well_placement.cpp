#include "flow_well_placement.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace cutaway::generators {
namespace {

constexpr double kFlankShare = 0.15;       ///< share of the field's length along the dip that is a flank
constexpr double kWellSpacingColumns = 10; ///< about one well per this many columns along a flank
constexpr int kMaxWellsPerFlank = 4;
constexpr double kStretchMiddle = 0.6;    ///< share of a flank's stretch a well is preferably picked from

struct Direction {
    double x = 1;
    double y = 0;
    double slope = 0;
};

/// Least-squares plane top_depth = a + b x + c y over the columns; the direction of (b, c), or,
/// where the plane is flatter than kMinimumDip, the longer axis of the columns' spread pointing
/// the way the plane deepens along it.
Direction down_dip_direction(const std::vector<ColumnSummary>& columns) {
    double mx = 0, my = 0, mz = 0;
    for (const ColumnSummary& c : columns) {
        mx += c.x;
        my += c.y;
        mz += c.top_depth;
    }
    const double n = double(columns.size());
    mx /= n;
    my /= n;
    mz /= n;
    double sxx = 0, sxy = 0, syy = 0, sxz = 0, syz = 0;
    for (const ColumnSummary& c : columns) {
        const double x = c.x - mx, y = c.y - my, z = c.top_depth - mz;
        sxx += x * x;
        sxy += x * y;
        syy += y * y;
        sxz += x * z;
        syz += y * z;
    }
    const double det = sxx * syy - sxy * sxy;
    double b = 0, c = 0;  // the plane's slopes east and north; 0 when the columns fix no plane
    if (det > 1e-12 * (sxx * syy)) {
        b = (syy * sxz - sxy * syz) / det;
        c = (sxx * syz - sxy * sxz) / det;
    }
    const double slope = std::hypot(b, c);
    if (slope >= kMinimumDip) return {b / slope, c / slope, slope};
    if (sxx >= syy) return {b < 0 ? -1.0 : 1.0, 0, std::abs(b)};
    return {0, c < 0 ? -1.0 : 1.0, std::abs(c)};
}

/// Position across the dip (along the strike), metres.
double along_strike(const ColumnSummary& c, const Direction& d) { return -c.x * d.y + c.y * d.x; }

struct Flank {
    std::vector<DeckWell> wells;
    double spacing = 0;  ///< the flank's width along the strike over its well count, metres
};

/// Wells on the flank of `candidates`: one per kWellSpacingColumns columns of its width along the
/// strike (1 to kMaxWellsPerFlank), the width split into equal stretches, in each the column of
/// highest k h around it (ColumnSummary::neighbourhood_kh), taken from the stretch's middle
/// (kStretchMiddle of it) unless that has no candidate, so wells of neighbouring stretches stand apart.
Flank pick_wells(const std::vector<const ColumnSummary*>& candidates, const Direction& d, double cell_size,
                 const std::string& prefix) {
    double t_min = std::numeric_limits<double>::infinity(), t_max = -t_min;
    for (const ColumnSummary* c : candidates) {
        t_min = std::min(t_min, along_strike(*c, d));
        t_max = std::max(t_max, along_strike(*c, d));
    }
    const double width = t_max - t_min;
    const int count = std::clamp(int(std::lround(width / (kWellSpacingColumns * cell_size))), 1, kMaxWellsPerFlank);
    std::vector<const ColumnSummary*> best_middle(std::size_t(count), nullptr), best_any(std::size_t(count), nullptr);
    for (const ColumnSummary* c : candidates) {
        const double position = width > 0 ? count * (along_strike(*c, d) - t_min) / width : 0;
        const int stretch = std::clamp(int(position), 0, count - 1);
        const bool middle = std::abs(position - stretch - 0.5) <= 0.5 * kStretchMiddle;
        for (auto* best : {&best_any, middle ? &best_middle : nullptr}) {
            if (!best) continue;
            const ColumnSummary*& chosen = (*best)[std::size_t(stretch)];
            if (!chosen || c->neighbourhood_kh > chosen->neighbourhood_kh) chosen = c;
        }
    }
    Flank flank;
    flank.spacing = std::max(width, cell_size) / count;
    for (std::size_t n = 0; n < best_any.size(); ++n)
        if (const ColumnSummary* c = best_middle[n] ? best_middle[n] : best_any[n])
            flank.wells.push_back({prefix + std::to_string(flank.wells.size() + 1), *c});
    return flank;
}

/// Drops the columns on the grid's outer boundary when others remain: a well there has half a
/// cell of reservoir around it on one side and takes less water than its k h promises.
void keep_inner_columns(std::vector<const ColumnSummary*>& candidates, const grid::GridDims& dims) {
    const auto inner = [&](const ColumnSummary* c) {
        return c->i > 0 && c->j > 0 && c->i < dims.nx - 1 && c->j < dims.ny - 1;
    };
    if (std::any_of(candidates.begin(), candidates.end(), inner))
        candidates.erase(std::remove_if(candidates.begin(), candidates.end(), [&](const ColumnSummary* c) { return !inner(c); }),
                         candidates.end());
}

double mean_along(const std::vector<DeckWell>& wells, const Direction& d) {
    double sum = 0;
    for (const DeckWell& w : wells) sum += w.column.x * d.x + w.column.y * d.y;
    return sum / double(wells.size());
}

}  // namespace

WellPlacement place_wells(const grid::CornerPointGrid& grid) {
    const std::vector<ColumnSummary> columns = active_columns(grid);
    if (columns.size() < 2)
        throw std::invalid_argument("--deck: expected at least two columns of active cells for injectors and "
                                    "producers, found " + std::to_string(columns.size()));
    const Direction d = down_dip_direction(columns);
    constexpr double inf = std::numeric_limits<double>::infinity();
    double s_min = inf, s_max = -inf, t_min = inf, t_max = -inf, footprint = 0, kh = 0;
    for (const ColumnSummary& c : columns) {
        const double s = c.x * d.x + c.y * d.y, t = along_strike(c, d);
        s_min = std::min(s_min, s);
        s_max = std::max(s_max, s);
        t_min = std::min(t_min, t);
        t_max = std::max(t_max, t);
        footprint += c.footprint;
        kh += c.kh;
    }
    const double cell_size = std::sqrt(footprint / double(columns.size()));
    if (!(s_max - s_min > 0.5 * cell_size))
        throw std::invalid_argument("--deck: expected active columns spread along the dip for injectors and "
                                    "producers on opposite flanks, found them all in one row");
    const double band = std::max(kFlankShare * (s_max - s_min), 0.5 * cell_size);
    std::vector<const ColumnSummary*> down_dip, up_dip;
    for (const ColumnSummary& c : columns) {
        const double s = c.x * d.x + c.y * d.y;
        if (s >= s_max - band) down_dip.push_back(&c);
        else if (s <= s_min + band) up_dip.push_back(&c);
    }
    keep_inner_columns(down_dip, grid.dims());
    keep_inner_columns(up_dip, grid.dims());

    WellPlacement placement;
    placement.down_dip_x = d.x;
    placement.down_dip_y = d.y;
    placement.dip = d.slope;
    placement.strike_extent = t_max - t_min;
    placement.mean_column_kh = kh / double(columns.size());
    Flank injectors = pick_wells(down_dip, d, cell_size, "INJ");
    Flank producers = pick_wells(up_dip, d, cell_size, "PROD");
    placement.injectors = std::move(injectors.wells);
    placement.producers = std::move(producers.wells);
    placement.injector_spacing = injectors.spacing;
    placement.producer_spacing = producers.spacing;
    if (placement.producers.empty())
        throw std::invalid_argument("--deck: expected active columns on the up-dip flank for producers, found none");
    placement.flank_distance = mean_along(placement.injectors, d) - mean_along(placement.producers, d);
    return placement;
}

}  // namespace cutaway::generators

#include "distributed/global_model.h"

#include <cmath>
#include <limits>

#include "grid/cell_geometry.h"
#include "grid/order_statistic.h"

namespace cutaway::distributed {
namespace {

constexpr double kNone = -std::numeric_limits<double>::infinity();

/// The whole model's depth direction (CornerPointGrid::depth_direction): corner 0 of cell
/// (0,0,0)'s top against corner 4 of (0,0,NZ-1)'s bottom, from the ranks holding them.
int global_depth_direction(const MpiSession& mpi, const ModelPart& part) {
    const grid::IjkBox& b = part.box;
    std::vector<double> corners{kNone, kNone};
    if (b.i0 == 0 && b.j0 == 0 && b.k0 == 0) corners[0] = part.grid.zcorn().corner_depth(0, 0, 0, 0);
    if (b.i0 == 0 && b.j0 == 0 && b.k1 == part.whole.nz - 1)
        corners[1] = part.grid.zcorn().corner_depth(0, 0, b.k1 - b.k0, 4);
    mpi.max(corners);
    return corners[0] <= corners[1] ? 1 : -1;
}

}  // namespace

grid::Box3 global_bounds(const MpiSession& mpi, const ModelPart& part) {
    const grid::Box3 own = grid::grid_bounds(part.grid);
    std::vector<double> extremes{-own.min.x, -own.min.y, -own.min.z, own.max.x, own.max.y, own.max.z};
    mpi.max(extremes);
    grid::Box3 bounds;
    bounds.min = {-extremes[0], -extremes[1], -extremes[2]};
    bounds.max = {extremes[3], extremes[4], extremes[5]};
    return bounds;
}

pipeline::ModelFrame global_model_frame(const MpiSession& mpi, const ModelPart& part, const grid::Box3& bounds,
                                        double z_scale) {
    pipeline::ModelFrame frame = pipeline::frame_from_bounds(bounds, global_depth_direction(mpi, part), z_scale);
    // Every column's top-most and bottom-most active layer over the whole model: a max of the
    // parts' (the top as a negated layer), over the whole model's columns.
    std::vector<int> top, bottom;
    pipeline::active_layer_span(part.grid, top, bottom);
    const grid::GridDims& d = part.grid.dims();
    const std::size_t columns = std::size_t(part.whole.nx) * std::size_t(part.whole.ny);
    std::vector<double> span(2 * columns, kNone);
    for (int j = 0; j < d.ny; ++j)
        for (int i = 0; i < d.nx; ++i) {
            const std::size_t own = std::size_t(j) * std::size_t(d.nx) + std::size_t(i);
            if (top[own] < 0) continue;
            const std::size_t whole = std::size_t(j + part.box.j0) * std::size_t(part.whole.nx) + std::size_t(i + part.box.i0);
            span[2 * whole] = -double(top[own] + part.box.k0);
            span[2 * whole + 1] = double(bottom[own] + part.box.k0);
        }
    mpi.max(span);
    for (int j = 0; j < d.ny; ++j)
        for (int i = 0; i < d.nx; ++i) {
            const std::size_t own = std::size_t(j) * std::size_t(d.nx) + std::size_t(i);
            const std::size_t whole = std::size_t(j + part.box.j0) * std::size_t(part.whole.nx) + std::size_t(i + part.box.i0);
            const bool any = span[2 * whole + 1] != kNone;
            top[own] = any ? int(-span[2 * whole]) : -1;
            bottom[own] = any ? int(span[2 * whole + 1]) : -1;
        }
    span = {};
    pipeline::OutlineSearch search(frame);
    search.consider_columns(part.grid, {part.box.i0, part.box.j0, part.box.k0}, part.whole.nx, top, bottom);
    const std::vector<double> own = search.packed();
    const std::vector<double> all = mpi.all_gather(own);
    for (int r = 0; r < mpi.size(); ++r)
        search.merge(std::vector<double>(all.begin() + std::ptrdiff_t(std::size_t(r) * own.size()),
                                         all.begin() + std::ptrdiff_t(std::size_t(r + 1) * own.size())));
    frame.outline = search.outline();
    return frame;
}

grid::PrimaryRange global_value_range(const MpiSession& mpi, const grid::PrimaryRange& own) {
    std::vector<double> extremes{-double(own.min), double(own.max)};
    mpi.max(extremes);
    return {float(-extremes[0]), float(extremes[1])};
}

grid::PrimaryRange global_range_for_fraction(const MpiSession& mpi, const std::vector<float>& own_active_values,
                                             double fraction, float max) {
    grid::check_fraction(fraction);
    std::vector<std::uint64_t> count{own_active_values.size()};
    mpi.sum(count);
    const std::size_t active = count[0];
    grid::OrderStatistic select(active - grid::primary_count_for_fraction(fraction, active));
    do {
        for (float value : own_active_values) select.add(value);
        mpi.sum(select.counts());
    } while (select.finish_pass());
    return {select.value(), max};
}

}  // namespace cutaway::distributed

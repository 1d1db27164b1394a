#include "distributed/rank_blocks.h"

#include <stdexcept>

namespace cutaway::distributed {

SlabAxis slab_axis_from_name(const std::string& name) {
    if (name == "i") return SlabAxis::i;
    if (name == "j") return SlabAxis::j;
    if (name == "k") return SlabAxis::k;
    throw std::invalid_argument("--rank-slabs: expected i, j or k, found '" + name + "'");
}

const char* slab_axis_name(SlabAxis axis) { return axis == SlabAxis::i ? "i" : axis == SlabAxis::j ? "j" : "k"; }

int layer_count(const grid::GridDims& d, SlabAxis axis) { return axis == SlabAxis::i ? d.nx : axis == SlabAxis::j ? d.ny : d.nz; }

namespace {

/// The box of every cell with layers [lo, hi] along `axis`.
grid::IjkBox layers_box(const grid::GridDims& d, SlabAxis axis, int lo, int hi) {
    grid::IjkBox box = grid::IjkBox::whole(d);
    (axis == SlabAxis::i ? box.i0 : axis == SlabAxis::j ? box.j0 : box.k0) = lo;
    (axis == SlabAxis::i ? box.i1 : axis == SlabAxis::j ? box.j1 : box.k1) = hi;
    return box;
}

}  // namespace

std::vector<std::uint64_t> active_per_layer(const grid::CornerPointGrid& grid, const grid::IjkBox& box,
                                            const grid::GridDims& dims, SlabAxis axis) {
    std::vector<std::uint64_t> active(std::size_t(layer_count(dims, axis)), 0);
    const int offset = axis == SlabAxis::i ? box.i0 : axis == SlabAxis::j ? box.j0 : box.k0;
    for (std::size_t cell = 0; cell < grid.cell_count(); ++cell) {
        if (!grid.active(cell)) continue;
        const grid::CellIjk c = grid::cell_ijk(grid.dims(), cell);
        ++active[std::size_t(offset + (axis == SlabAxis::i ? c.i : axis == SlabAxis::j ? c.j : c.k))];
    }
    return active;
}

std::optional<grid::IjkBox> equal_slab(const grid::GridDims& dims, int ranks, int rank, SlabAxis axis) {
    const int layers = layer_count(dims, axis);
    const int lo = int(std::int64_t(layers) * rank / ranks), end = int(std::int64_t(layers) * (rank + 1) / ranks);
    if (lo == end) return std::nullopt;
    return layers_box(dims, axis, lo, end - 1);
}

std::vector<grid::IjkBox> split_into_slabs(const grid::CornerPointGrid& grid, int ranks, SlabAxis axis) {
    return split_into_slabs(active_per_layer(grid, grid::IjkBox::whole(grid.dims()), grid.dims(), axis), grid.dims(),
                            ranks, axis);
}

std::vector<grid::IjkBox> split_into_slabs(const std::vector<std::uint64_t>& active, const grid::GridDims& d,
                                           int ranks, SlabAxis axis) {
    const int layers = layer_count(d, axis);
    int occupied = 0;
    std::uint64_t total = 0;
    for (std::uint64_t count : active) {
        occupied += count > 0 ? 1 : 0;
        total += count;
    }
    if (ranks < 1 || ranks > occupied)
        throw std::invalid_argument("mpirun -np " + std::to_string(ranks) + ": the model has " + std::to_string(occupied) +
                                    " " + slab_axis_name(axis) + "-layers with active cells; expected at most " +
                                    std::to_string(occupied) + " ranks for " + slab_axis_name(axis) +
                                    " slabs (--rank-slabs i|j|k picks the axis)");
    // Greedy cut: slab r ends once it holds its share of the active cells, leaving at least one
    // occupied layer for each later rank.
    std::vector<grid::IjkBox> boxes;
    int begin = 0, occupied_left = occupied;
    std::size_t taken = 0;
    for (int r = 0; r < ranks; ++r) {
        const std::size_t target = total * std::size_t(r + 1) / std::size_t(ranks);
        int end = begin;  // exclusive
        bool has_active = false;
        while (end < layers) {
            const bool occupied_layer = active[std::size_t(end)] > 0;
            if (has_active && occupied_layer && (taken >= target || occupied_left <= ranks - 1 - r)) break;
            taken += active[std::size_t(end)];
            has_active = has_active || occupied_layer;
            occupied_left -= occupied_layer ? 1 : 0;
            ++end;
        }
        if (r == ranks - 1) end = layers;
        boxes.push_back(layers_box(d, axis, begin, end - 1));
        begin = end;
    }
    return boxes;
}

}  // namespace cutaway::distributed

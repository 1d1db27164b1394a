#pragma once
// ZCORN depths without the duplicated layer interfaces most grids carry.
//
// Eclipse stores 2NX x 2NY x 2NZ depths: for each layer k the top-face corners (plane 2k) and
// the bottom-face corners (plane 2k+1). In nearly every simulation grid the bottom of layer k
// equals the top of layer k+1 corner by corner, so the store starts "compact" with NZ+1 planes
// (slot k+b for plane 2k+b) and switches, exactly, to the full 2NZ planes the first time a top
// differs from the bottom above it. Either way every value reads back bit-identical.
#include <cstddef>
#include <functional>
#include <vector>

#include "grid/grid_dims.h"
#include "grid/zeroed_allocator.h"

namespace cutaway::grid {

class ZcornStore {
public:
    ZcornStore() = default;
    /// An empty store for `dims`, to be filled by push() in Eclipse order.
    explicit ZcornStore(GridDims dims);
    /// A complete store from the 8*NX*NY*NZ Eclipse-ordered depths.
    static ZcornStore from_values(GridDims dims, const std::vector<double>& values);
    /// Bytes the compact layout needs (the minimum a load allocates for ZCORN).
    static std::size_t compact_bytes(GridDims dims);

    /// Bytes the full layout needs (2NZ planes).
    static std::size_t full_bytes(GridDims dims);

    /// Appends the next depth in Eclipse order (x fastest, then y, then plane).
    void push(double depth);
    /// Appends `count` copies of `depth` (an `N*value` item) a plane at a time, at memory speed;
    /// calls `before_expanding()` (which may throw, leaving the store compact) just before
    /// switching to the full layout allocates full_bytes().
    void push_repeated(double depth, std::size_t count, const std::function<void()>& before_expanding);
    std::size_t pushed() const { return pushed_; }
    bool complete() const { return pushed_ == dims_.zcorn_value_count(); }

    /// Depth of value `index` in Eclipse order (0 <= index < 8*cells).
    double value(std::size_t index) const {
        const std::size_t plane = index / plane_size_;
        return depths_[slot_of(plane) * plane_size_ + index % plane_size_];
    }
    /// Depth of corner `corner` of cell (i, j, k); corner bit 0: i+1 side, bit 1: j+1 side,
    /// bit 2: bottom face.
    double corner_depth(int i, int j, int k, int corner) const {
        const std::size_t plane = std::size_t(2 * k + (corner >> 2));
        const std::size_t row = std::size_t(2 * j + ((corner >> 1) & 1));
        const std::size_t col = std::size_t(2 * i + (corner & 1));
        return depths_[(slot_of(plane) * std::size_t(2 * dims_.ny) + row) * std::size_t(2 * dims_.nx) + col];
    }

    bool is_compact() const { return compact_; }
    std::size_t bytes() const { return depths_.capacity() * sizeof(double); }
    const GridDims& dims() const { return dims_; }

private:
    std::size_t slot_of(std::size_t plane) const { return compact_ ? (plane + 1) / 2 : plane; }
    /// Whether push(depth) would switch the store to the full layout.
    bool push_expands(double depth) const {
        const std::size_t plane = pushed_ / plane_size_;
        return compact_ && plane % 2 == 0 && plane > 0 && depths_[slot_of(plane) * plane_size_ + pushed_ % plane_size_] != depth;
    }
    void expand_to_full();
    /// Of `run` depths from `slot` on, how many equal `depth` before the first that does not. A slot
    /// nothing non-zero was written to holds +0 throughout and is not read: reading untouched
    /// memory maps a page on kernels without a shared zero page (issue 18's reproducer then held 1.5 GB).
    std::size_t same_run(const double* slot, std::size_t slot_index, std::size_t run, double depth) const;

    GridDims dims_{};
    std::size_t plane_size_ = 1;  // 2NX * 2NY
    /// Zeroed without being touched (zeroed_allocator.h): planes of +0 depths are never written,
    /// so they cost no resident memory until another value lands in them.
    using Depths = std::vector<double, ZeroedAllocator<double>>;
    Depths depths_;
    std::vector<bool> slot_written_;  ///< per compact slot: a non-zero depth was written to it
    std::size_t pushed_ = 0;
    bool compact_ = true;
};

}  // namespace cutaway::grid

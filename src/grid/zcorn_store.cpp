#include "grid/zcorn_store.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cutaway::grid {

ZcornStore::ZcornStore(GridDims dims)
    : dims_(dims), plane_size_(std::size_t(4) * std::size_t(dims.nx) * std::size_t(dims.ny)) {
    if (plane_size_ == 0) plane_size_ = 1;
    depths_.resize(plane_size_ * std::size_t(dims.nz + 1));  // zero, untouched
    slot_written_.assign(std::size_t(dims.nz + 1), false);
}

std::size_t ZcornStore::compact_bytes(GridDims dims) {
    return std::size_t(4) * std::size_t(dims.nx) * std::size_t(dims.ny) * std::size_t(dims.nz + 1) *
           sizeof(double);
}

std::size_t ZcornStore::full_bytes(GridDims dims) { return dims.zcorn_value_count() * sizeof(double); }

ZcornStore ZcornStore::from_values(GridDims dims, const std::vector<double>& values) {
    if (values.size() != dims.zcorn_value_count())
        throw std::invalid_argument("ZcornStore::from_values: expected " +
                                    std::to_string(dims.zcorn_value_count()) + " depths, got " +
                                    std::to_string(values.size()));
    ZcornStore store(dims);
    for (double z : values) store.push(z);
    return store;
}

void ZcornStore::push(double depth) {
    if (complete()) throw std::logic_error("ZcornStore::push: store is already complete");
    const std::size_t plane = pushed_ / plane_size_;
    const std::size_t offset = pushed_ % plane_size_;
    if (push_expands(depth)) expand_to_full();
    depths_[slot_of(plane) * plane_size_ + offset] = depth;
    if (compact_ && depth != 0.0) slot_written_[slot_of(plane)] = true;
    ++pushed_;
}

void ZcornStore::push_repeated(double depth, std::size_t count, const std::function<void()>& before_expanding) {
    if (count > dims_.zcorn_value_count() - pushed_)
        throw std::logic_error("ZcornStore::push_repeated: more depths than the grid has");
    while (count > 0) {
        const std::size_t plane = pushed_ / plane_size_;
        const std::size_t run = std::min(count, plane_size_ - pushed_ % plane_size_);
        double* slot = depths_.data() + slot_of(plane) * plane_size_ + pushed_ % plane_size_;
        if (compact_ && plane % 2 == 0 && plane > 0) {
            // A top plane stays compact while it repeats the bottom above (already in the slot).
            const std::size_t same = same_run(slot, slot_of(plane), run, depth);
            pushed_ += same;
            count -= same;
            if (same < run) {
                before_expanding();
                expand_to_full();
            }
            continue;
        }
        // The slot is written here for the first time and starts at +0: +0 needs no write.
        if (depth != 0.0 || std::signbit(depth)) std::fill(slot, slot + run, depth);
        if (compact_ && depth != 0.0) slot_written_[slot_of(plane)] = true;
        pushed_ += run;
        count -= run;
    }
}

std::size_t ZcornStore::same_run(const double* slot, std::size_t slot_index, std::size_t run, double depth) const {
    if (!slot_written_[slot_index]) return depth == 0.0 ? run : 0;  // +0 throughout (-0 compares equal, as below)
    return std::size_t(std::find_if(slot, slot + run, [depth](double d) { return d != depth; }) - slot);
}

void ZcornStore::expand_to_full() {
    // Every value pushed so far is consistent with the compact layout, so reading each plane
    // through the compact slots reproduces it exactly. Only the values pushed so far are copied:
    // the rest stays +0 and untouched, as push_repeated expects of a slot it has not written (the
    // current top plane's compact slot holds the bottom above, which must not leak into it).
    Depths full;
    full.resize(plane_size_ * std::size_t(2 * dims_.nz));
    for (std::size_t plane = 0; plane * plane_size_ < pushed_; ++plane) {
        const double* from = depths_.data() + slot_of(plane) * plane_size_;
        std::copy(from, from + std::min(plane_size_, pushed_ - plane * plane_size_), full.data() + plane * plane_size_);
    }
    depths_ = std::move(full);
    compact_ = false;
}

}  // namespace cutaway::grid

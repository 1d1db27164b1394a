#pragma once
// Depth of every layer interface on every pillar, once per distinct block offset meeting at the
// pillar (a pillar on a fault carries one depth column per side). ZCORN is read from here. Only
// the columns and interfaces of one box of cells are kept (the whole model, or one block of it).
#include <cstdint>
#include <vector>

#include "grid/primary_selection.h"
#include "horizon_surfaces.h"
#include "layering.h"
#include "pillar_leans.h"

namespace cutaway::generators {

class PillarDepths {
public:
    /// `offsets`: per column downward block offset (metres); `leans`: per pillar; `box`: the
    /// cells whose corners are kept (whole-model indices).
    PillarDepths(const ModelFrame& frame, const HorizonSurfaces& horizons, const Layering& layering,
                 const std::vector<PillarLean>& leans, const std::vector<double>& offsets, const grid::IjkBox& box);

    /// Depth of interface `k` (0 = top of layer 0, NZ = base) at corner `corner` (bit 0: i+1,
    /// bit 1: j+1) of column (i, j), metres; whole-model indices within the box (k up to its
    /// last layer + 1).
    double depth(int i, int j, int corner, int k) const {
        const std::size_t column = std::size_t(j - box_.j0) * std::size_t(box_.i1 - box_.i0 + 1) + std::size_t(i - box_.i0);
        const std::size_t variant = corner_variant_[4 * column + std::size_t(corner)];
        return depths_[variant * std::size_t(interfaces_) + std::size_t(k - box_.k0)];
    }
    /// Interface depths lifted to the one above where a tilted pillar met the horizons out of
    /// order (the repair of crossed layers).
    std::size_t repaired_depths() const { return repaired_; }
    /// Depth columns stored: pillars + one per extra fault side.
    std::size_t variants() const { return depths_.size() / std::size_t(interfaces_); }

private:
    grid::IjkBox box_;
    int interfaces_ = 0;                         ///< kept per variant: the box's layers + 1
    std::vector<double> depths_;                 ///< variant-major
    std::vector<std::uint32_t> corner_variant_;  ///< 4 per column of the box
    std::size_t repaired_ = 0;
};

}  // namespace cutaway::generators

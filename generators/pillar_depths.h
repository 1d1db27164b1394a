#pragma once
// Depth of every layer interface on every pillar, once per distinct block offset meeting at the
// pillar (a pillar on a fault carries one depth column per side). ZCORN is read from here.
#include <cstdint>
#include <vector>

#include "horizon_surfaces.h"
#include "layering.h"
#include "pillar_leans.h"

namespace cutaway::generators {

class PillarDepths {
public:
    /// `offsets`: per column downward block offset (metres); `leans`: per pillar.
    PillarDepths(const ModelFrame& frame, const HorizonSurfaces& horizons, const Layering& layering,
                 const std::vector<PillarLean>& leans, const std::vector<double>& offsets);

    /// Depth of interface `k` (0 = top of layer 0, NZ = base) at corner `corner` (bit 0: i+1,
    /// bit 1: j+1) of column (i, j), metres.
    double depth(int i, int j, int corner, int k) const {
        const std::size_t variant = corner_variant_[4 * (std::size_t(j) * std::size_t(nx_) + std::size_t(i)) +
                                                    std::size_t(corner)];
        return depths_[variant * std::size_t(interfaces_) + std::size_t(k)];
    }
    /// Interface depths lifted to the one above where a tilted pillar met the horizons out of
    /// order (the repair of crossed layers).
    std::size_t repaired_depths() const { return repaired_; }
    /// Depth columns stored: pillars + one per extra fault side.
    std::size_t variants() const { return depths_.size() / std::size_t(interfaces_); }

private:
    int nx_ = 0;
    int interfaces_ = 0;
    std::vector<double> depths_;                ///< variant-major, NZ+1 each
    std::vector<std::uint32_t> corner_variant_;  ///< 4 per column
    std::size_t repaired_ = 0;
};

}  // namespace cutaway::generators

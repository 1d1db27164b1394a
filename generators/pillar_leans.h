#pragma once
// Pillars along a fault trace lean with the fault's dip so the fault surface follows the plane;
// pillars up to `lean_spread_pillars` away share a fading part of the lean, which keeps the
// cells beside the fault from shearing abruptly.
#include <cstdint>
#include <vector>

#include "faults.h"
#include "model_frame.h"

namespace cutaway::generators {

/// Horizontal drift of a pillar per metre of depth (x, y), measured from its mid-depth point.
struct PillarLean {
    double x = 0;
    double y = 0;
};

/// True for pillar (pi, pj) when its neighbouring columns lie on both sides of fault `f`.
bool on_fault_trace(const ModelFrame& frame, const std::vector<std::uint64_t>& masks, int pi, int pj, int f);

/// Leans per pillar (GridDims::pillar_index order) and the factor they were scaled by.
struct PillarLeans {
    std::vector<PillarLean> leans;
    double scale = 1;  ///< 1, or less where neighbouring pillars would otherwise cross
};

/// A pillar at Chebyshev distance r from a trace pillar of fault f gets (1 - r / (spread + 1))
/// of f's lean; the largest share per fault is kept and the faults' leans add. Where traces meet,
/// the sum can make neighbouring pillars cross within `depth_reach` metres of mid-depth (cells
/// turn inside out), so all leans are scaled down until neighbours stay at least half a cell
/// apart there.
PillarLeans pillar_leans(const ModelFrame& frame, const std::vector<FaultPlane>& faults,
                         const std::vector<std::uint64_t>& masks, int spread, double depth_reach);

}  // namespace cutaway::generators

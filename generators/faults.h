#pragma once
// Faults as planes: each splits the model into a footwall and a hanging wall that drops by the
// fault's throw. Which side a cell column lies on is decided by CGAL's exact oriented_side.
#include <cstdint>
#include <string>
#include <vector>

#include "deterministic_random.h"
#include "model_frame.h"

namespace cutaway::generators {

struct FaultPlane {
    grid::Point3 anchor;       ///< a point on the plane at mid-depth, metres
    grid::Point3 normal;       ///< unit normal, pointing into the hanging wall
    double throw_m = 0;        ///< downward offset of the hanging wall, metres
    double strike_deg = 0;     ///< clockwise from north
    double dip_deg = 90;       ///< from horizontal
    /// Horizontal drift per metre of depth of a line lying in the plane along its dip (x, y);
    /// zero for a vertical fault. Pillars on the trace lean by this much.
    double lean_x = 0;
    double lean_y = 0;

    std::string describe() const;
};

/// `parameters.fault_count` planes through the middle 60% of the model, strikes within the
/// azimuth spread, throws uniform in the throw range.
std::vector<FaultPlane> make_faults(const GeneratorParameters& parameters, const ModelFrame& frame,
                                    DeterministicRandom& random);

/// Per column (ModelFrame::column_index order): bit f set when the column centre lies strictly
/// on fault f's hanging-wall side (CGAL exact oriented_side; a centre on the plane is footwall).
std::vector<std::uint64_t> hanging_wall_masks(const std::vector<FaultPlane>& faults, const ModelFrame& frame);

/// Downward offset of each column, metres: the sum of the throws of the faults whose hanging
/// wall holds it (summed in fault order, so equal masks give bit-identical offsets).
std::vector<double> column_offsets(const std::vector<FaultPlane>& faults, const std::vector<std::uint64_t>& masks);

}  // namespace cutaway::generators

#pragma once
// Regular box models built in memory: the invariant checks' ground truth and the memory benchmark's
// input. Vertical pillars on a regular lattice, flat layers, optionally one vertical fault.
#include "grid/corner_point_grid.h"

namespace cutaway::grid {

struct BoxGridSpec {
    GridDims dims{2, 2, 2};
    Point3 cell_size{100, 100, 10};  ///< dx, dy, dz in model units
    Point3 origin{0, 0, 1000};       ///< x, y of pillar (0,0); depth of the top surface
    /// Cells with i >= fault_i are shifted down by fault_throw (no fault when fault_throw is 0).
    int fault_i = 0;
    double fault_throw = 0;
};

CornerPointGrid make_box_grid(const BoxGridSpec& spec);

}  // namespace cutaway::grid

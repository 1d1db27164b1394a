#pragma once
// Shape check of one generated cell with CGAL's exact orientation predicate on the 8 corner
// tetrahedra (each corner with its i, j and k neighbours).
#include "grid/cell_geometry.h"

namespace cutaway::generators {

enum class CellValidity {
    valid,
    pinched,     ///< all four pillar edges have zero length: a pinch-out, no volume
    inverted,    ///< some corner tetrahedron is left-handed: the cell is turned inside out
    degenerate,  ///< some corner tetrahedron is flat although its pillar edge has length
};

/// Corners in grid::CellCorners order (bit 0: i+1, bit 1: j+1, bit 2: bottom), z down, so a
/// valid cell's corner b sees (b^1, b^2, b^4) positively oriented when b has an even number of
/// bits set and negatively otherwise. Wedges (some pillar edges of zero length) are valid.
CellValidity check_cell(const grid::CellCorners& corners);

}  // namespace cutaway::generators

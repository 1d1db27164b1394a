#pragma once
// Whether a fault face lies wholly against active cells: the cells of the column across it cover
// it, so no ray leaves the model through it (the rear shell, src/cutaway/rear_shell_depth.h, can
// leave it out). Fault faces are mostly like that: only where the throw lifts one side above the
// other's top, or drops it below its bottom, does a part of the face bound the model.
#include <vector>

#include "grid/face_classification.h"
#include "grid/zcorn_store.h"

namespace cutaway::grid {

/// Whether the active cells of the column across the I or J face `side` of cell (i, j, k) cover
/// that face entirely: a stack of them through the neighbour at the same k, each one's bottom the
/// next one's top on both shared pillars (the stack's faces then tile one quad between the two
/// pillars), reaches at or above the face's top and at or below its bottom on both pillars. No
/// tolerance: a sliver left uncovered by any amount keeps the face. `active`: one per Eclipse
/// cell. False for K faces, faces on the grid's edge, an inactive neighbour, and cells (the face's
/// or the stack's) whose top and bottom are equal or inverted on a pillar.
bool face_covered_across(const ZcornStore& zcorn, const std::vector<bool>& active, int i, int j, int k, FaceSide side);

}  // namespace cutaway::grid

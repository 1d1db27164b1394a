// The culling's counters (src/cutaway/visibility/visible_faces.h CullingCounts), cleared each
// frame: bricks and cells culled by visibility/classify_bricks.comp and cull_cells.comp, the
// faces selected in all by visibility/scan_bricks.comp, read by finish_culling.comp.
#include "common/shared_constants.h"
layout(std430, binding = ssbo_culling_counters) buffer Culling {
    uint bricks_culled;
    uint cells_culled;
    uint cells_behind;
    uint cells_straddling;
    uint faces_requested;  // faces selected, including any beyond the capacity
};

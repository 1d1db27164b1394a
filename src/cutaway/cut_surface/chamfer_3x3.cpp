// Chamfer 3x3 with steps (1, sqrt2) on the GPU (gpu_chamfer.cpp): lengths up to 8.2% too long, the cut never above exact.
#include "cutaway/cut_surface/cone_field_strategy.h"

namespace cutaway::pipeline {

CutSurfaceEntry chamfer_3x3_entry() { return chamfer_entry("chamfer-3x3", cone_field::ChamferMask::city_diagonal_3x3); }

}  // namespace cutaway::pipeline

// Chamfer 3x3 <3,4> (Borgefors) on the GPU (gpu_chamfer.cpp): lengths within about +-5.5%.
#include "cutaway/cut_surface/cone_field_strategy.h"

namespace cutaway::pipeline {

CutSurfaceEntry chamfer_34_entry() { return chamfer_entry("chamfer-34", cone_field::ChamferMask::borgefors_3x3); }

}  // namespace cutaway::pipeline

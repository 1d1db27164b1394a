// Chamfer 5x5 <5,7,11> (Borgefors) on the GPU (gpu_chamfer.cpp): lengths within about +-2%.
#include "cutaway/cut_surface/cone_field_strategy.h"

namespace cutaway::pipeline {

CutSurfaceEntry chamfer_5x5_entry() { return chamfer_entry("chamfer-5x5", cone_field::ChamferMask::borgefors_5x5); }

}  // namespace cutaway::pipeline

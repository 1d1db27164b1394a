// Jump flooding (Rong and Tan 2006), steps N/2 .. 1, on the GPU (gpu_jump_flooding.cpp).
#include "cutaway/cut_surface/cone_field_strategy.h"

namespace cutaway::pipeline {

CutSurfaceEntry jfa_entry() { return jump_flooding_entry("jfa", cone_field::JfaVariant::jfa); }

}  // namespace cutaway::pipeline

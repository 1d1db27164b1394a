// Jump flooding (Rong and Tan 2006), steps N/2 .. 1; CPU reference implementation.
#include "cutaway/cut_surface/cone_field_strategy.h"

namespace cutaway::pipeline {

CutSurfaceEntry jfa_entry() { return jump_flooding_entry("jfa", cone_field::JfaVariant::jfa); }

}  // namespace cutaway::pipeline

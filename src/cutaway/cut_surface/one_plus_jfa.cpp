// 1+JFA: a pass with step 1, then jump flooding.
#include "cutaway/cut_surface/cone_field_strategy.h"

namespace cutaway::pipeline {

CutSurfaceEntry one_plus_jfa_entry() { return jump_flooding_entry("1+jfa", cone_field::JfaVariant::one_plus_jfa); }

}  // namespace cutaway::pipeline

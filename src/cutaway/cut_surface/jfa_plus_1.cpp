// JFA+1: jump flooding, then one more pass with step 1.
#include "cutaway/cut_surface/cone_field_strategy.h"

namespace cutaway::pipeline {

CutSurfaceEntry jfa_plus_1_entry() { return jump_flooding_entry("jfa+1", cone_field::JfaVariant::jfa_plus_1); }

}  // namespace cutaway::pipeline

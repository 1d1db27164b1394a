// JFA+2: jump flooding, then passes with steps 2 and 1.
#include "cutaway/cut_surface/cone_field_strategy.h"

namespace cutaway::pipeline {

CutSurfaceEntry jfa_plus_2_entry() { return jump_flooding_entry("jfa+2", cone_field::JfaVariant::jfa_plus_2); }

}  // namespace cutaway::pipeline

// JFA^2: jump flooding run twice.
#include "cutaway/cut_surface/cone_field_strategy.h"

namespace cutaway::pipeline {

CutSurfaceEntry jfa_squared_entry() { return jump_flooding_entry("jfa2", cone_field::JfaVariant::jfa_squared); }

}  // namespace cutaway::pipeline

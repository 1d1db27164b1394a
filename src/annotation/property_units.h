#pragma once
// Units of the reservoir properties a colour bar may show, keyed by the Eclipse keyword.
#include <string>
#include <string_view>

namespace cutaway::annotation {

/// The unit of Eclipse property `keyword` as a colour bar prints it ("frac" for PORO and the
/// saturations, "mD" for permeabilities, "-" for NTG, ...) in Eclipse's `unit_system` (METRIC,
/// FIELD, LAB or PVT-M; empty: METRIC, as GRDECL files and presets are taken); empty when we do not
/// know it.
std::string property_unit(std::string_view keyword, std::string_view unit_system = "METRIC");

}  // namespace cutaway::annotation

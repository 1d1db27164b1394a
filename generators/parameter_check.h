#pragma once
// Refusals of generator parameters in the form every `cutaway` option error takes
// ("--option: expected WHAT, found 'VALUE'"): each parameter is named by the command-line option
// that sets it, so a value from a preset and one typed by the user read the same way.
#include <string>

namespace cutaway::generators {

/// `value` as the shortest text that reads back exactly (0.5, 1e+30, 65).
std::string parameter_text(double value);

/// Throws std::invalid_argument("OPTION: expected EXPECTED, found 'FOUND'") unless `ok`.
void require_parameter(bool ok, const std::string& option, const std::string& expected, const std::string& found);
/// The same with a number found.
void require_parameter(bool ok, const std::string& option, const std::string& expected, double found);

}  // namespace cutaway::generators

#pragma once
// Numbers as the generated OPM Flow decks write them.
#include <string>

namespace cutaway::generators {

/// `value` with 7 significant digits, shortest form ("0.5", "1.2e-05", "214.3567"): what the
/// Eclipse deck parser reads back within a relative 5e-8.
std::string deck_number(double value);

}  // namespace cutaway::generators

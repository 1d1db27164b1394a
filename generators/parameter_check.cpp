#include "generators/parameter_check.h"

#include <charconv>
#include <stdexcept>

namespace cutaway::generators {

std::string parameter_text(double value) {
    char buffer[32];
    return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}

void require_parameter(bool ok, const std::string& option, const std::string& expected, const std::string& found) {
    if (!ok) throw std::invalid_argument(option + ": expected " + expected + ", found '" + found + "'");
}

void require_parameter(bool ok, const std::string& option, const std::string& expected, double found) {
    require_parameter(ok, option, expected, parameter_text(found));
}

}  // namespace cutaway::generators

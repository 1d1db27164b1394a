#include "deck_number.h"

#include <charconv>

namespace cutaway::generators {

std::string deck_number(double value) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, 7);
    return std::string(buffer, result.ptr);
}

}  // namespace cutaway::generators

#include "annotation/property_units.h"

#include <array>
#include <utility>

namespace cutaway::annotation {

std::string property_unit(std::string_view keyword) {
    // Eclipse METRIC units of the keywords our models and the shared decks carry.
    static constexpr std::array<std::pair<std::string_view, std::string_view>, 14> units{{
        {"PORO", "frac"}, {"NTG", "-"}, {"PERMX", "mD"}, {"PERMY", "mD"}, {"PERMZ", "mD"},
        {"SWAT", "frac"}, {"SOIL", "frac"}, {"SGAS", "frac"}, {"PRESSURE", "bar"}, {"DEPTH", "m"},
        {"TOPS", "m"}, {"DX", "m"}, {"DY", "m"}, {"DZ", "m"},
    }};
    for (const auto& [name, unit] : units)
        if (name == keyword) return std::string(unit);
    return {};
}

}  // namespace cutaway::annotation

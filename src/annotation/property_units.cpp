#include "annotation/property_units.h"

#include <array>
#include <utility>

namespace cutaway::annotation {

namespace {

/// Pressure and length units of Eclipse's unit systems (the Eclipse reference manual's table of
/// units: METRIC bar and m, FIELD psia and ft, LAB atm and cm, PVT-M atm and m).
struct UnitSystem {
    std::string_view name;
    std::string_view pressure;
    std::string_view length;
};
constexpr std::array<UnitSystem, 4> unit_systems{{
    {"METRIC", "bar", "m"}, {"FIELD", "psia", "ft"}, {"LAB", "atm", "cm"}, {"PVT-M", "atm", "m"},
}};

}  // namespace

std::string property_unit(std::string_view keyword, std::string_view unit_system) {
    const auto* system = &unit_systems.front();
    for (const UnitSystem& s : unit_systems)
        if (s.name == unit_system) system = &s;
    // The keywords our models and the shared decks carry; "P" and "L" stand for the system's
    // pressure and length units.
    static constexpr std::array<std::pair<std::string_view, std::string_view>, 14> units{{
        {"PORO", "frac"}, {"NTG", "-"}, {"PERMX", "mD"}, {"PERMY", "mD"}, {"PERMZ", "mD"},
        {"SWAT", "frac"}, {"SOIL", "frac"}, {"SGAS", "frac"}, {"PRESSURE", "P"}, {"DEPTH", "L"},
        {"TOPS", "L"}, {"DX", "L"}, {"DY", "L"}, {"DZ", "L"},
    }};
    for (const auto& [name, unit] : units) {
        if (name != keyword) continue;
        if (unit == "P") return std::string(system->pressure);
        if (unit == "L") return std::string(system->length);
        return std::string(unit);
    }
    return {};
}

}  // namespace cutaway::annotation

#include "flow_fluid_model.h"

#include <cmath>
#include <sstream>

#include "deck_number.h"

namespace cutaway::generators::flow_fluids {
namespace {

/// SWOF: Sw, krw, krow, Pcow (0) from Swi to 1 - Sor in equal steps, then Sw = 1 (krw 1, krow 0).
std::string swof_text() {
    std::ostringstream out;
    out << "SWOF\n-- Sw  krw  krow  Pcow (bar): Corey, exponents " << deck_number(water_corey_exponent) << " and "
        << deck_number(oil_corey_exponent) << "\n";
    const double mobile = 1 - connate_water - residual_oil;
    for (int row = 0; row < relperm_rows; ++row) {
        const double normalised = double(row) / double(relperm_rows - 1);  // 0 at Swi, 1 at 1 - Sor
        const double sw = connate_water + normalised * mobile;
        const double krw = water_relperm_at_residual_oil * std::pow(normalised, water_corey_exponent);
        const double krow = oil_relperm_at_connate_water * std::pow(1 - normalised, oil_corey_exponent);
        out << "  " << deck_number(sw) << ' ' << deck_number(krw) << ' ' << deck_number(krow) << " 0\n";
    }
    out << "  1 1 0 0 /\n\n";
    return out.str();
}

}  // namespace

std::string props_section_text() {
    const std::string p_ref = deck_number(reference_pressure_bar);
    std::ostringstream out;
    out << "PVTW\n-- Pref (bar)  Bw  Cw (1/bar)  viscosity (cP)  viscosibility\n  " << p_ref << ' '
        << deck_number(water_formation_factor) << ' ' << deck_number(water_compressibility) << ' '
        << deck_number(water_viscosity_cp) << " 0 /\n\n";
    out << "PVCDO\n-- Pref (bar)  Bo  Co (1/bar)  viscosity (cP)  viscosibility\n  " << p_ref << ' '
        << deck_number(oil_formation_factor) << ' ' << deck_number(oil_compressibility) << ' '
        << deck_number(oil_viscosity_cp) << " 0 /\n\n";
    out << "DENSITY\n-- oil  water  gas (kg/m3)\n  " << deck_number(oil_density) << ' ' << deck_number(water_density)
        << ' ' << deck_number(gas_density) << " /\n\n";
    out << "ROCK\n-- Pref (bar)  Cr (1/bar)\n  " << p_ref << ' ' << deck_number(rock_compressibility) << " /\n\n";
    out << swof_text();
    return out.str();
}

}  // namespace cutaway::generators::flow_fluids

#pragma once
// The fluids and rock-fluid model of the generated OPM Flow decks (METRIC units): dead oil and
// water, Corey relative permeabilities whose end points are the synthetic flood's (Swi, Sor of
// SaturationModel), no capillary pressure, so the simulated and the synthetic fronts share their
// saturation range.
#include <string>

#include "water_saturation.h"

namespace cutaway::generators::flow_fluids {

constexpr double connate_water = SaturationModel::connate;     ///< Swi, fraction
constexpr double residual_oil = SaturationModel::residual_oil;  ///< Sor, fraction
constexpr double water_corey_exponent = 2;
constexpr double oil_corey_exponent = 2;
constexpr double water_relperm_at_residual_oil = 0.4;  ///< krw at Sw = 1 - Sor
constexpr double oil_relperm_at_connate_water = 0.9;   ///< kro at Sw = Swi
constexpr int relperm_rows = 11;                       ///< SWOF rows from Swi to 1 - Sor (then Sw = 1)

constexpr double reference_pressure_bar = 200;
constexpr double water_viscosity_cp = 0.5;
constexpr double oil_viscosity_cp = 1.0;    ///< a light oil: water-oil mobility ratio below 1, a sharp front
constexpr double water_formation_factor = 1.01;   ///< Bw at the reference pressure, rm3/sm3
constexpr double oil_formation_factor = 1.05;     ///< Bo at the reference pressure, rm3/sm3
constexpr double water_compressibility = 4.5e-5;  ///< 1/bar
constexpr double oil_compressibility = 1e-4;      ///< 1/bar
constexpr double rock_compressibility = 5e-5;     ///< 1/bar
constexpr double oil_density = 850;               ///< kg/m3 at surface conditions
constexpr double water_density = 1020;            ///< kg/m3
constexpr double gas_density = 0.9;               ///< kg/m3 (DENSITY needs one; there is no gas)

constexpr double vertical_permeability_ratio = 0.1;  ///< PERMZ / PERMX (PERMY = PERMX)
constexpr double wellbore_diameter_m = 0.2;

/// Pressure gradient of a fluid column of `density` (kg/m3), bar per metre.
constexpr double pressure_gradient_bar_per_m(double density) { return density * 9.80665 / 1e5; }

/// The PROPS keywords PVTW, PVCDO, DENSITY, ROCK and SWOF, as deck text.
std::string props_section_text();

}  // namespace cutaway::generators::flow_fluids

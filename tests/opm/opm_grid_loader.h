#pragma once
// Loading a GRDECL file into OPM's EclipseGrid the way a simulator deck does, shared by the
// OPM reference tests (tests/opm, tests/generators).
#include <filesystem>
#include <string>

#include <opm/input/eclipse/Deck/Deck.hpp>
#include <opm/input/eclipse/EclipseState/Grid/EclipseGrid.hpp>
#include <opm/input/eclipse/Parser/ErrorGuard.hpp>
#include <opm/input/eclipse/Parser/InputErrorAction.hpp>
#include <opm/input/eclipse/Parser/ParseContext.hpp>
#include <opm/input/eclipse/Parser/Parser.hpp>

namespace cutaway::test {

inline Opm::ParseContext lenient_parse_context() {
    // Every shared file parses with the default (strict) context too; these keys are relaxed
    // to warnings so that a GRDECL export with stray text or keywords OPM does not know still
    // reaches EclipseGrid. Missing RUNSPEC/PROPS/... sections are expected for a grid-only deck.
    Opm::ParseContext context;
    for (const std::string& key :
         {Opm::ParseContext::PARSE_MISSING_SECTIONS, Opm::ParseContext::PARSE_UNKNOWN_KEYWORD,
          Opm::ParseContext::PARSE_RANDOM_TEXT, Opm::ParseContext::PARSE_RANDOM_SLASH,
          Opm::ParseContext::PARSE_EXTRA_RECORDS, Opm::ParseContext::PARSE_EXTRA_DATA,
          Opm::ParseContext::PARSE_MISSING_DIMS_KEYWORD})
        context.update(key, Opm::InputError::WARN);
    return context;
}

/// The grid file as a simulator deck sees it: "GRID / INCLUDE 'file' /". OPM 2022.10 ignores
/// ACTNUM outside a GRID section, so a bare GRDECL file would come back all active.
/// Throws whatever OPM throws.
inline Opm::EclipseGrid opm_grid(const std::filesystem::path& grid_file) {
    Opm::Parser parser;
    const Opm::ParseContext context = lenient_parse_context();
    Opm::ErrorGuard errors;
    const Opm::Deck deck = parser.parseString(
        "GRID\nINCLUDE\n '" + std::filesystem::absolute(grid_file).string() + "' /\n", context, errors);
    errors.clear();  // warnings only (lenient context); do not let ~ErrorGuard print them
    return Opm::EclipseGrid(deck);
}

}  // namespace cutaway::test

#pragma once
// `--wells`: which wells a frame draws and where they come from. Given once or twice: a FILE (a
// deck or any file of deck keywords: its WELSPECS and COMPDAT) and/or `all`, `none` or a
// comma-separated list of names. A value naming an existing file, or holding a '/', or ending in
// a deck extension (.DATA, .GRDECL, .INC, .SCH, case-insensitive) is a FILE.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "wells/well.h"

namespace cutaway::wells {

struct WellsOption {
    enum class Which { unset, all, none, named };
    std::optional<std::filesystem::path> file;  ///< the wells' file; else a simulator case's restart
    Which which = Which::unset;                 ///< unset: all of a FILE's, none otherwise
    std::vector<std::string> names;             ///< Which::named

    /// Whether the frame draws any well (a FILE given, or a selection other than none).
    bool draws() const;
};

/// Whether `value` of --wells names a file rather than wells.
bool names_a_file(const std::string& value);

/// The values of --wells (0..2 of them). Throws std::invalid_argument naming --wells for two files,
/// two selections, or an empty name.
WellsOption parse_wells_option(const std::vector<std::string>& values);

/// The wells `option` selects from `wells` (in `wells`' order; `source` says where they came
/// from). Throws std::invalid_argument naming --wells, the unknown name and the known ones.
std::vector<Well> select_wells(const std::vector<Well>& wells, const WellsOption& option, const std::string& source);

}  // namespace cutaway::wells

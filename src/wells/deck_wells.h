#pragma once
// Wells from an Eclipse deck (.DATA) or any file of deck keywords (a GRDECL, an include file),
// through opm-common's parser: WELSPECS (name, wellhead), COMPDAT (connections; I, J defaulted
// or 0 mean the wellhead's column) and the control keywords for kind and status.
#include <filesystem>
#include <vector>

#include "wells/well.h"

namespace cutaway::wells {

/// The wells of `file` in WELSPECS order. Only WELSPECS, COMPDAT, WCONPROD, WCONHIST, WCONINJE
/// and WCONINJH are read (INCLUDE files followed); every other keyword is skipped unread. Kind and
/// status come from the first control record naming the well (its state when the schedule starts;
/// well-name patterns such as 'PROD*' match), else the kind is unknown and the status open.
/// COMPDAT naming a cell twice keeps the first position and the last state. Throws
/// io::BadInputError naming the file (and line) for a missing or unparsable file, a file without
/// WELSPECS, a COMPDAT of an undefined well or with a layer below 1 or K1 > K2.
std::vector<Well> read_deck_wells(const std::filesystem::path& file);

}  // namespace cutaway::wells

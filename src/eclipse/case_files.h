#pragma once
// A simulator case on disk: CASE.EGRID with CASE.INIT and CASE.UNRST beside it (each optional).
#include <filesystem>
#include <optional>
#include <string>

namespace cutaway::eclipse {

struct CaseFiles {
    std::filesystem::path egrid;
    std::optional<std::filesystem::path> init;   ///< CASE.INIT when it exists (static arrays)
    std::optional<std::filesystem::path> unrst;  ///< CASE.UNRST when it exists (report steps)
};

/// The case a MODEL argument names: `CASE.EGRID` (any letter case of the extension; the file need
/// not exist, reading it then fails with the file's name), or `CASE` when no file `CASE` exists but
/// `CASE.EGRID` (or `CASE.egrid`) does. std::nullopt for anything else (a GRDECL file, a preset).
/// INIT and UNRST are looked for with the extension in the EGRID's letter case.
std::optional<CaseFiles> find_case_files(const std::string& model);

}  // namespace cutaway::eclipse

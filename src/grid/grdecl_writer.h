#pragma once
// GRDECL writer: SPECGRID, metadata, COORD, ZCORN, ACTNUM and every property, with `N*value`
// runs and shortest round-trip number formatting, so read -> write -> read gives identical arrays.
#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "grid/corner_point_grid.h"

namespace cutaway::grid {

struct GrdeclWriteOptions {
    /// Lines written as `--` comments at the top of the file (e.g. generator parameters).
    std::vector<std::string> header_comments;
    /// Properties written (static and dynamic), when set; the rest are left out (a simulator deck
    /// takes only the keywords it knows). Unset: every property.
    std::optional<std::vector<std::string>> only_properties = std::nullopt;
};

void write_grdecl(std::ostream& out, const CornerPointGrid& grid, const GrdeclWriteOptions& options = {});
/// Written under a temporary name and renamed; throws io::OutputError naming the file and the
/// reason when it cannot be written (no partial file is left).
void write_grdecl(const std::filesystem::path& path, const CornerPointGrid& grid,
                  const GrdeclWriteOptions& options = {});

}  // namespace cutaway::grid

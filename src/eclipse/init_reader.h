#pragma once
// Static per-cell arrays of CASE.INIT (PORO, PERMX, NTG, PORV, SATNUM, ...) onto the grid read
// from the case's EGRID, through opm-common's EclIO::EInit.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

#include "grid/corner_point_grid.h"

namespace cutaway::eclipse {

/// The cell arrays of `init`'s global grid: REAL and DOUB arrays become float properties, INTE
/// arrays integer properties, one value per cell (INIT holds one per active cell for most arrays,
/// spread over the cells with 0 in inactive ones; PORV and others already hold one per cell).
/// `only`: the one array wanted (absent from the file: nothing is added); std::nullopt: all.
/// Sets the grid's metadata().unit_system from INTEHEAD.
/// Throws EclipseError for a missing, truncated or foreign file, an INIT of another grid
/// (dimensions or active count differ from `grid`'s), or arrays needing more than
/// `memory_limit_bytes` (checked before they are read).
void add_init_properties(grid::CornerPointGrid& grid, const std::filesystem::path& init, std::size_t memory_limit_bytes,
                         const std::optional<std::string>& only);

}  // namespace cutaway::eclipse

#pragma once
// CASE.EGRID (Eclipse binary grid, as OPM Flow, Eclipse and other simulators write it) to a
// corner-point grid, read through opm-common's EclIO::EGrid.
#include <cstddef>
#include <filesystem>

#include "grid/corner_point_grid.h"

namespace cutaway::eclipse {

/// The global grid of `egrid` (local grid refinements are not read): COORD (6 values per pillar,
/// model units), ZCORN (8 depths per cell, Eclipse order), ACTNUM (all active when absent),
/// MAPAXES, MAPUNITS and GRIDUNIT as metadata (not applied, as for GRDECL). Throws EclipseError
/// naming the file (and array) for a missing, truncated or foreign file, a radial grid, an array of
/// the wrong length, or a grid needing more than `memory_limit_bytes` (checked before the arrays
/// are read).
grid::CornerPointGrid read_egrid(const std::filesystem::path& egrid, std::size_t memory_limit_bytes);

/// NX, NY, NZ of `egrid` without reading its arrays.
grid::GridDims read_egrid_dims(const std::filesystem::path& egrid);

}  // namespace cutaway::eclipse

#pragma once
// Well paths in the model's coordinates (x east, y north, z as the grid's depths): from a wellhead
// above the model down through the centres of the connected cells. What the well tubes are drawn
// around and what a `well:NAME[,R]` cut volume follows.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "grid/corner_point_grid.h"
#include "grid/point3.h"
#include "wells/well.h"

namespace cutaway::wells {

/// Where wellheads stand: the depth of the model's top (its active cells' shallowest corner) and
/// a level above it by a quarter of the model's thickness, so that every wellhead is seen from any
/// camera above the model.
struct WellheadLevel {
    double top = 0;   ///< model units, the grid's depth axis
    double head = 0;
};
WellheadLevel wellhead_level(const grid::CornerPointGrid& grid);
/// The same for a model whose active cells span `bounds` (grid::grid_bounds) with depths growing
/// with k (`depth_direction` +1) or shrinking (-1).
WellheadLevel wellhead_level(const grid::Box3& bounds, int depth_direction);

/// The polyline of `well` (at least 2 points): the wellhead's column centre (mean of its 4
/// pillars) at level.head; if the first connection lies in another column, the wellhead's column
/// at that connection's depth (a vertical hole, then the deviation); then each connection's cell
/// centre (mean of its 8 corners) in order. A well without connections ends at the model's top.
/// Needs the grid's corner depths.
std::vector<grid::Point3> well_path(const Well& well, const grid::CornerPointGrid& grid, const WellheadLevel& level);

/// What a path is built from, computable by parts of a model: the wellhead's column centre at
/// level.head and at level.top (the column's line: pillars are straight), then each connection's
/// cell centre. `part_origin`: the whole-model indices of `part`'s cell (0, 0, 0); a point whose
/// column or cell `part` does not hold is -infinity in x, y and z, so that the parts' points
/// combine by an element-wise max (distributed rendering).
std::vector<grid::Point3> well_path_points(const Well& well, const grid::CornerPointGrid& part, const WellheadLevel& level,
                                           const grid::CellIjk& part_origin = {0, 0, 0});
/// The path from `points` (well_path_points of the whole model).
std::vector<grid::Point3> assemble_well_path(const Well& well, const std::vector<grid::Point3>& points);

/// Every well's path by name: what the cut volumes' `well:NAME[,R]` looks up.
using WellPathMap = std::map<std::string, std::vector<grid::Point3>>;
WellPathMap well_paths(const std::vector<Well>& wells, const grid::CornerPointGrid& grid);

/// The path of well `name`, or std::nullopt for a name `paths` does not hold.
std::optional<std::vector<grid::Point3>> find_well_path(const WellPathMap& paths, const std::string& name);

/// A tube radius that reads at the model's scale (model units): a fifth of the median horizontal
/// cell width (the smaller of a column's two top edges), at least 0.3% of the model's horizontal
/// diagonal (so that the tubes of a model of millions of thin columns still show).
double default_well_radius(const grid::CornerPointGrid& grid);
/// The same with the diagonal of `bounds` (the whole model's, for a part of it).
double default_well_radius(const grid::CornerPointGrid& grid, const grid::Box3& bounds);

}  // namespace cutaway::wells

#pragma once
// Where the generated deck's wells go, from the model's geology: a plane fitted to the top of the
// active columns gives the dip; water injectors stand on the down-dip flank and producers on the
// up-dip flank, each in the column of highest k h (with its neighbours) within its stretch of the
// flank, completed in every active layer of that column.
#include <string>
#include <vector>

#include "column_summaries.h"
#include "grid/corner_point_grid.h"

namespace cutaway::generators {

struct DeckWell {
    std::string name;         ///< "INJ1", "PROD2", ...
    ColumnSummary column;     ///< its column; completed in every layer of column.layers
};

struct WellPlacement {
    std::vector<DeckWell> injectors;  ///< on the down-dip flank
    std::vector<DeckWell> producers;  ///< on the up-dip flank
    /// Horizontal unit vector (x, y) from the producers' flank to the injectors' flank: the
    /// direction in which the fitted top deepens, or the field's longer axis (towards its deeper
    /// end) where the top is flatter than `kMinimumDip`.
    double down_dip_x = 1;
    double down_dip_y = 0;
    double dip = 0;           ///< slope of the fitted top along down_dip, metres of depth per metre
    double flank_distance = 0;  ///< metres along down_dip between the two flanks' wells (mean)
    double strike_extent = 0;   ///< metres across the field, perpendicular to down_dip
    /// Metres along the strike per well on each flank (the flank's width over its well count).
    double injector_spacing = 0;
    double producer_spacing = 0;
    double mean_column_kh = 0;  ///< mean k h of the active columns (ColumnSummary::kh), mD m
};

/// Slope (m/m) below which the fitted top counts as flat.
constexpr double kMinimumDip = 1e-3;

/// Throws std::invalid_argument ("--deck: expected ...") when `grid` lacks PERMX or NTG, or has
/// no two active columns at different positions along the dip.
WellPlacement place_wells(const grid::CornerPointGrid& grid);

}  // namespace cutaway::generators

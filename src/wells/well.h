#pragma once
// A well as the cutaway draws it: its name, kind, status, wellhead column and the cells it
// connects to, from a deck (WELSPECS, COMPDAT, WCON*) or a restart file (ZWEL, IWEL, ICON).
#include <array>
#include <string>
#include <vector>

#include "grid/grid_dims.h"

namespace cutaway::wells {

enum class WellKind { producer, injector, unknown };
enum class WellStatus { open, stop, shut, automatic };

/// One connection to a cell, 0-based indices.
struct WellConnection {
    int i = 0, j = 0, k = 0;
    bool open = true;
};

struct Well {
    std::string name;
    /// From WCONPROD/WCONHIST (producer) or WCONINJE/WCONINJH (injector), or the restart's IWEL;
    /// unknown when no control keyword names the well.
    WellKind kind = WellKind::unknown;
    std::string injected_phase;  ///< WATER | GAS | OIL | MULTI for an injector, empty otherwise
    WellStatus status = WellStatus::open;
    int head_i = 0, head_j = 0;  ///< the wellhead's column, 0-based
    std::vector<WellConnection> connections;  ///< in the order the deck or file lists them
};

const char* to_string(WellKind kind);
const char* to_string(WellStatus status);

/// Linear RGB of the well's tube: injectors blue, producers red-orange, a well of unknown kind
/// magenta (none of them in the property colour map's range of hues), a shut or stopped well grey.
std::array<float, 3> well_colour(const Well& well);

/// Throws io::BadInputError naming `source`, the well and the cell when a wellhead column or a
/// connection lies outside `dims`.
void check_within_grid(const std::vector<Well>& wells, const grid::GridDims& dims, const std::string& source);

}  // namespace cutaway::wells

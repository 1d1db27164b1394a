#pragma once
// What the generator built, for the file header and the command's output.
#include <cstddef>
#include <string>
#include <vector>

namespace cutaway::generators {

struct GenerationReport {
    std::size_t cells = 0;
    std::size_t active_cells = 0;
    std::size_t pinched_cells = 0;         ///< zero thickness at all four pillars: inactive
    std::size_t clustered_inactive = 0;    ///< made inactive by the inactive fraction (not pinched)
    std::size_t inverted_cells = 0;        ///< left-handed corner found by orientation: inactive
    std::size_t degenerate_cells = 0;      ///< flat corner with a pillar edge of length: inactive
    std::size_t repaired_depths = 0;       ///< interface depths lifted below the one above
    std::size_t depth_columns = 0;         ///< pillars + extra fault sides
    double lean_scale = 1;                 ///< factor applied to fault leans so pillars never cross
    int horizons = 0;
    std::size_t triangles_per_horizon = 0;
    std::vector<std::string> faults;       ///< one description per fault plane
    std::vector<std::string> injectors;    ///< "i j" of each injector column (0-based)
    std::vector<double> swept_fraction;    ///< per SWAT step

    /// `key = value` lines.
    std::vector<std::string> lines() const;
};

}  // namespace cutaway::generators

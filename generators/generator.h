#pragma once
// The synthetic faulted corner-point generator: parameters in, grid with PORO, PERMX, NTG,
// FACIES and SWAT steps out. Same parameters (seed included) give the same grid, bit for bit.
#include <cstddef>
#include <string>
#include <vector>

#include "generation_report.h"
#include "generator_parameters.h"
#include "grid/corner_point_grid.h"
#include "grid/primary_selection.h"
#include "progress_log.h"

namespace cutaway::generators {

struct GeneratedModel {
    grid::CornerPointGrid grid;
    GenerationReport report;
    /// Per column (i fastest): downward offset of its fault block, metres. Columns with
    /// different offsets meet at a fault; equal offsets share their corners.
    std::vector<double> column_offsets;
};

/// The dynamic property the generator writes (one array per time step, GeneratorParameters::time_steps).
inline const std::string generated_dynamic_property = "SWAT";

/// Default memory limit of the generator (bytes): the 10M-cell preset's budget.
constexpr std::size_t kDefaultGeneratorMemoryLimit = std::size_t(4) << 30;

/// Throws std::invalid_argument for bad parameters (see validate()).
GeneratedModel generate_model(const GeneratorParameters& parameters, ProgressLog& progress,
                              std::size_t memory_limit_bytes = kDefaultGeneratorMemoryLimit);

/// The cells of `box` (inclusive, whole-model indices) of generate_model's model, generated
/// alone: its COORD pillars, ZCORN, ACTNUM, PORO, PERMX, NTG and FACIES equal the same block cut
/// from the whole model bit for bit, in memory that scales with the box (plus per-column and
/// per-pillar arrays and the random fields' coarse lattices). Quantities over the whole model
/// (the pinch-out and inactive-cluster thresholds) are streamed exactly. No SWAT: the water
/// flood is a shortest-path pass over the whole model (generate_model adds it). The report
/// counts the box's cells; column_offsets are the whole model's.
GeneratedModel generate_block(const GeneratorParameters& parameters, const grid::IjkBox& box, ProgressLog& progress,
                              std::size_t memory_limit_bytes = kDefaultGeneratorMemoryLimit);

/// Header comment lines of the written file: every parameter, then the report.
std::vector<std::string> header_lines(const GeneratorParameters& parameters, const GenerationReport& report);

}  // namespace cutaway::generators

#pragma once
// The synthetic faulted corner-point generator: parameters in, grid with PORO, PERMX, NTG,
// FACIES and SWAT steps out. Same parameters (seed included) give the same grid, bit for bit.
#include <cstddef>
#include <string>
#include <vector>

#include "generation_report.h"
#include "generator_parameters.h"
#include "grid/corner_point_grid.h"
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

/// Header comment lines of the written file: every parameter, then the report.
std::vector<std::string> header_lines(const GeneratorParameters& parameters, const GenerationReport& report);

}  // namespace cutaway::generators

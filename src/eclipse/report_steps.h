#pragma once
// The report steps of CASE.UNRST (a unified restart file): their simulator numbers, dates and
// wells, and per-cell arrays (SWAT, SGAS, PRESSURE, ...) read on demand, one step at a time,
// through opm-common's EclIO::ERst.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "grid/corner_point_grid.h"

namespace cutaway::eclipse {

/// One connection of a well to a cell (ICON), 0-based cell indices.
struct ConnectionAtStep {
    int i = 0, j = 0, k = 0;
    bool open = true;
};

/// A well as the restart file's IWEL/ZWEL (and ICON) arrays describe it at one report step.
struct WellAtStep {
    std::string name;
    std::string type;    ///< producer | water_injector | gas_injector | oil_injector | unknown
    std::string status;  ///< open | stop | shut | auto, else the IWEL number
    int head_i = -1, head_j = -1;  ///< wellhead column, 0-based
    /// In the file's order; filled by ReportSteps::wells_with_connections only.
    std::vector<ConnectionAtStep> connections;
};

struct ReportStep {
    std::size_t index = 0;   ///< position in the file, 0-based (`--time-step`)
    int report_number = 0;   ///< the simulator's report number (SEQNUM)
    int year = 0, month = 0, day = 0;  ///< INTEHEAD's calendar date of the step
    double elapsed_days = 0;           ///< DOUBHEAD item 1: days since the start of the run
    std::vector<WellAtStep> wells;
    std::string date() const;  ///< YYYY-MM-DD
};

class ReportSteps {
public:
    /// Reads the step list of `unrst`, a restart of `grid` (its dimensions and active cells are
    /// checked against every step's INTEHEAD), and remembers ACTNUM to spread active-cell arrays
    /// over the cells. Holds no cell array. `memory_limit_bytes`: what one step's read may use
    /// (checked here and at each read). Throws EclipseError for a missing, truncated or foreign
    /// file, or a restart of another grid.
    ReportSteps(std::filesystem::path unrst, const grid::CornerPointGrid& grid, std::size_t memory_limit_bytes);

    const std::filesystem::path& file() const { return file_; }
    const std::vector<ReportStep>& steps() const { return steps_; }
    std::size_t step_count() const { return steps_.size(); }
    /// Arrays with one value per active cell at some step (REAL or DOUB), sorted; SOIL among them
    /// when derived.
    const std::vector<std::string>& property_names() const { return names_; }
    bool has_property(const std::string& name) const;
    /// The first step's INTEHEAD unit convention: METRIC, FIELD, LAB or PVT-M (empty: unknown).
    const std::string& unit_system() const { return unit_system_; }
    /// SOIL computed as 1 - SWAT - SGAS (1 - SWAT without SGAS): the file holds SWAT but no SOIL.
    bool soil_derived() const { return soil_derived_; }

    /// `name` at step `index` (0-based), one value per cell with 0 in inactive cells. Opens the
    /// file afresh and reads that step's array (SWAT and SGAS for a derived SOIL) and nothing else,
    /// so a read holds one step's arrays (read_bytes()) whatever was read before. Throws
    /// EclipseError for a step out of range, an array the step does not hold, an array whose length
    /// is not the active count, or a file that cannot be read any more.
    std::vector<float> values(const std::string& name, std::size_t index) const;
    /// The wells of step `index` (0-based) with their connections (ICON), read afresh from the
    /// file. Throws EclipseError for a step out of range or well arrays shorter than INTEHEAD says.
    std::vector<WellAtStep> wells_with_connections(std::size_t index) const;
    /// The most one values() call holds while reading: the per-cell result plus EclIO's arrays.
    std::size_t read_bytes() const;

private:
    std::filesystem::path file_;
    std::vector<std::uint8_t> actnum_;
    std::size_t active_count_ = 0;
    std::size_t memory_limit_bytes_ = 0;
    std::vector<ReportStep> steps_;
    std::vector<std::string> names_;
    bool soil_derived_ = false;
    std::string unit_system_;
};

}  // namespace cutaway::eclipse

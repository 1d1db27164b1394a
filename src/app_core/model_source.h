#pragma once
// MODEL arguments: a GRDECL file, `preset:NAME` for a synthetic model generated in memory, or a
// simulator case (`CASE.EGRID` or `CASE`, with CASE.INIT and CASE.UNRST beside it).
#include <cstddef>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "eclipse/report_steps.h"
#include "grid/corner_point_grid.h"
#include "grid/primary_selection.h"
#include "io/file_identity.h"

namespace cutaway::app {

struct LoadedModel {
    grid::CornerPointGrid grid;
    std::string description;  ///< file path or "preset:NAME (seed S)"
    double load_seconds = 0;
    std::vector<std::string> warnings;  ///< the GRDECL reader's (none for a preset)
    /// A simulator case's UNRST (null otherwise): its arrays are declared on the grid with their
    /// step count and held one step at a time (hold_property).
    std::shared_ptr<const eclipse::ReportSteps> report_steps;
    /// A block of a simulator case (load_block) has no report_steps but keeps the case's UNRST
    /// here for its wells (ReportSteps::wells_with_connections reads no cell array).
    std::shared_ptr<const eclipse::ReportSteps> block_wells_restart;
    /// A simulator case's INIT: arrays not read by load_model are read by hold_property.
    std::optional<std::filesystem::path> init_file;
};

/// Loads `model` (files read onto one grid, one preset:NAME, or one simulator case); throws
/// GrdeclError or eclipse::EclipseError for bad files, std::invalid_argument for unknown presets.
/// A simulator case holds no report step yet (hold_property); `only_property` limits the INIT
/// arrays read to that one.
/// `memory_limit_bytes` bounds what reading or generating may allocate. `only_property`: the one
/// property the caller will use (empty: the default, PORO), so a preset skips its water flood (the
/// SWAT steps: about a quarter of a generation's time and 4 bytes per cell and step) unless SWAT is
/// asked for; the other arrays are the same bit for bit (each stage has its own random stream).
/// std::nullopt keeps every property (the viewer switches between them).
/// `outputs`: the run's output files, refused (std::invalid_argument) when an INCLUDE names one,
/// before that INCLUDE is read (the files named on the command line are checked by the caller).
LoadedModel load_model(const std::vector<std::string>& model, std::size_t memory_limit_bytes,
                       const std::optional<std::string>& only_property = std::nullopt,
                       const std::vector<io::NamedFile>& outputs = {});

/// The files `model` names ("the model" each), none for a preset: what no output may overwrite.
std::vector<io::NamedFile> model_input_files(const std::vector<std::string>& model);

/// The property a frame shows when none is named: PORO, else the first static property, else the
/// first dynamic one; empty for a model without properties.
std::string default_property_name(const grid::CornerPointGrid& grid);

/// Whether `property` (empty: default_property_name) at `time_step` (-1: 0) needs no restart read:
/// not a simulator case's restart array, or that step already held. When false, hold_property
/// releases the array's step held before.
bool holds_time_step(const LoadedModel& model, const std::string& property, int time_step);
/// Puts a simulator case's `property` (empty: default_property_name) on the grid: an INIT array
/// not read yet is read, a restart array's report step `time_step` (-1: 0) is read and held,
/// releasing the step of that array held before. Does nothing for other properties and models.
/// Everything within `memory_limit_bytes` (what the grid holds counts). Throws
/// std::invalid_argument naming --time-step for a step beyond the file's, eclipse::EclipseError
/// for a file that cannot be read.
void hold_property(LoadedModel& model, const std::string& property, int time_step, std::size_t memory_limit_bytes);

/// What a frame showing `property` at report step `time_step` writes over itself, as animate does:
/// property, date (a simulator case's) and step; empty for a static property or no step (-1).
std::string step_caption(const LoadedModel& model, const std::string& property, int time_step);

/// The whole model's dimensions without loading it: a preset's, the files' SPECGRID/DIMENS
/// (read no further), or a simulator case's GRIDHEAD.
grid::GridDims model_dims(const std::vector<std::string>& model, std::size_t memory_limit_bytes);

/// Only the cells of `box` (whole-model indices) of the model load_model gives, equal to the same
/// box cut from it bit for bit, in memory that scales with the box: a preset generates only the
/// block (generators::generate_block), files keep only the block's ZCORN, ACTNUM and per-cell
/// values as they are parsed (grid::GrdeclReadOptions::block). `property`: the one the caller will
/// use (empty: the default); a preset's SWAT needs the whole model's flood and throws
/// std::invalid_argument. A simulator case is read whole and the box cut from it (EGRID holds
/// ZCORN as one array), with `property` at `time_step` held (hold_property). `outputs` as for load_model.
LoadedModel load_block(const std::vector<std::string>& model, const grid::IjkBox& box, std::size_t memory_limit_bytes,
                       const std::string& property, int time_step = -1, const std::vector<io::NamedFile>& outputs = {});

}  // namespace cutaway::app

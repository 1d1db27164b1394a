#pragma once
// MODEL arguments: a GRDECL file, or `preset:NAME` for a synthetic model generated in memory.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "grid/corner_point_grid.h"
#include "grid/primary_selection.h"
#include "io/file_identity.h"

namespace cutaway::app {

struct LoadedModel {
    grid::CornerPointGrid grid;
    std::string description;  ///< file path or "preset:NAME (seed S)"
    double load_seconds = 0;
    std::vector<std::string> warnings;  ///< the GRDECL reader's (none for a preset)
};

/// Loads `model` (files read onto one grid, or one preset:NAME); throws GrdeclError for bad files, std::invalid_argument for unknown presets.
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

/// The whole model's dimensions without loading it: a preset's, or the files' SPECGRID/DIMENS
/// (read no further).
grid::GridDims model_dims(const std::vector<std::string>& model, std::size_t memory_limit_bytes);

/// Only the cells of `box` (whole-model indices) of the model load_model gives, equal to the same
/// box cut from it bit for bit, in memory that scales with the box: a preset generates only the
/// block (generators::generate_block), files keep only the block's ZCORN, ACTNUM and per-cell
/// values as they are parsed (grid::GrdeclReadOptions::block). `property`: the one the caller will
/// use (empty: the default); a preset's SWAT needs the whole model's flood and throws
/// std::invalid_argument.
/// `outputs` as for load_model.
LoadedModel load_block(const std::vector<std::string>& model, const grid::IjkBox& box, std::size_t memory_limit_bytes,
                       const std::string& property, const std::vector<io::NamedFile>& outputs = {});

}  // namespace cutaway::app

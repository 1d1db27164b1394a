#pragma once
// Eclipse GRDECL reader: SPECGRID/DIMENS, COORD, ZCORN, ACTNUM, MAPAXES, GRIDUNIT, MAPUNITS,
// GDORIENT, per-cell property keywords, INCLUDE, NOECHO/ECHO. One or several files build one grid.
// Every malformed input raises GrdeclError naming file, line, keyword, expected and found.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "grid/corner_point_grid.h"
#include "grid/grdecl_error.h"
#include "grid/primary_selection.h"

namespace cutaway::grid {

struct GrdeclReadOptions {
    /// Refuse input whose file text (each file and its nested INCLUDEs, held while read) and arrays
    /// would need more than this many bytes, before allocating.
    std::size_t memory_limit_bytes = std::size_t(16) << 30;
    /// Deepest INCLUDE nesting accepted (loops are detected regardless).
    int max_include_depth = 32;
    /// Whether INCLUDE may open files (off for in-memory parsing such as fuzzing).
    bool allow_include = true;
    /// Keep only the cells of this box (whole-grid indices; it must lie within SPECGRID/DIMENS):
    /// ZCORN, ACTNUM and per-cell properties are filtered as they are parsed, so only the box's
    /// values are ever held; COORD is read whole (one line per pillar) and narrowed at finish().
    /// The grid finish() returns is the box's, equal to grid::extract_box of the whole grid.
    std::optional<IjkBox> block;
    /// Called with each INCLUDE's path (resolved against its file) and where it is named
    /// ("FILE:LINE") before the file is read: a caller refuses one its outputs would overwrite.
    std::function<void(const std::filesystem::path& include, const std::string& where)> before_include;
};

/// Reads GRDECL files into one grid. Files after the first may add properties only.
class GrdeclReader {
public:
    explicit GrdeclReader(GrdeclReadOptions options = {});
    ~GrdeclReader();
    GrdeclReader(const GrdeclReader&) = delete;
    GrdeclReader& operator=(const GrdeclReader&) = delete;

    void read_file(const std::filesystem::path& path);
    /// `name` stands for the file in messages; INCLUDE paths resolve against `base_dir`.
    void read_text(std::string_view text, const std::string& name, const std::filesystem::path& base_dir = {});

    /// The grid built from everything read; throws GrdeclError if SPECGRID/DIMENS, COORD or ZCORN
    /// is missing. Leaves the reader empty but for its warnings.
    CornerPointGrid finish();

    /// Non-fatal notes (unknown keywords skipped, redefinitions), "file:line: text".
    const std::vector<std::string>& warnings() const;

    struct State;  // opaque: the keywords read so far

private:
    friend GridDims read_grdecl_dims(const std::vector<std::filesystem::path>& files, const GrdeclReadOptions& options);
    std::unique_ptr<State> state_;
};

/// The grid dimensions of `files` (SPECGRID or DIMENS), reading no further than them; throws
/// GrdeclError like load_grdecl when they are missing or malformed.
GridDims read_grdecl_dims(const std::vector<std::filesystem::path>& files, const GrdeclReadOptions& options = {});

/// Reads `files` in order onto one grid (e.g. a grid file then its property files).
CornerPointGrid load_grdecl(const std::vector<std::filesystem::path>& files, const GrdeclReadOptions& options = {},
                            std::vector<std::string>* warnings = nullptr);

}  // namespace cutaway::grid

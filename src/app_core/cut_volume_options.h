#pragma once
// `--cut-volume SPEC` (repeatable), `--cut-volumes FILE.json` and `--primaries property|none`:
// the user's cut volumes (src/volumes/) in every front end that takes the scene options
// (render, animate, view, MPI render), turned into meshes once the model is known.
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cutaway/model_frame.h"
#include "shapes/triangle_mesh.h"
#include "volumes/cut_volume.h"
#include "volumes/volume_mesh.h"

namespace cutaway::app {

struct CutVolumeOptions {
    std::vector<std::string> specs;          ///< --cut-volume, as given
    std::string file;                        ///< --cut-volumes (empty: none)
    std::vector<volumes::CutVolume> parsed;  ///< the specs, parsed and checked while parsing
    std::string primaries = "property";      ///< --primaries

    bool any() const { return !specs.empty() || !file.empty(); }
    /// The options for stats.json's configuration.
    nlohmann::json describe() const;
};

/// Registers --cut-volume, --cut-volumes and --primaries on `command`; the specs are checked
/// while parsing (a bad one exits 2 naming it).
void add_cut_volume_options(CLI::App& command, CutVolumeOptions& options);
/// Fills `parsed` from `specs` (the command's callback calls it once parsing is done).
void finish_cut_volume_options(CutVolumeOptions& options);

/// The checks of --primaries none against the other options: something must cut (a volume) and
/// nothing may select primaries (`selects_primaries` names the option that would, empty if none);
/// `only_primaries`: --only primaries, which would draw nothing. Throws std::invalid_argument.
void check_primaries_none(const CutVolumeOptions& options, const std::string& selects_primaries, bool only_primaries);

/// The volumes of --cut-volumes then --cut-volume, with their closed meshes (model coordinates).
struct CutVolumeSet {
    std::vector<volumes::CutVolume> volumes;
    std::vector<shapes::TriangleMesh> meshes;
    /// [{"kind", "spec", parameters as in the JSON file, "triangles"}, ...] for stats.json.
    nlohmann::json describe() const;
};

/// Reads --cut-volumes and builds every volume's mesh. `wells`: the model's well paths (empty
/// while wells are not read: a `well:` volume is then refused as unknown); `frame`: the model's,
/// for the default well radius. Throws std::invalid_argument naming the spec, file or field.
/// `list` with every volume's mesh, as load_cut_volumes builds them (the viewer's edited list).
CutVolumeSet build_cut_volumes(std::vector<volumes::CutVolume> list, const pipeline::ModelFrame& frame,
                               const volumes::WellPaths& wells, std::size_t memory_limit_bytes);

CutVolumeSet load_cut_volumes(const CutVolumeOptions& options, const pipeline::ModelFrame& frame,
                              const volumes::WellPaths& wells, std::size_t memory_limit_bytes);

}  // namespace cutaway::app

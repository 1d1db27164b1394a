#pragma once
// The cut-volume list as JSON: what `--cut-volumes FILE` reads and the viewer saves.
//
//   {"volumes": [
//     {"kind": "box",      "min": [X0, Y0, Z0], "max": [X1, Y1, Z1]},
//     {"kind": "cylinder", "from": [X0, Y0, Z0], "to": [X1, Y1, Z1], "radius": R},
//     {"kind": "well",     "name": "P1", "radius": R},      (radius optional)
//     {"kind": "mesh",     "file": "salt.ply"}               (relative: to the JSON file's folder)
//   ]}
//
// Coordinates in the model's units, as for `--cut-volume`; a field not listed for its kind is refused.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "volumes/cut_volume.h"

namespace cutaway::volumes {

/// The volumes of `text`, a JSON document in the format above; `source` names it in messages and
/// relative mesh files are taken relative to `base_dir`. Throws std::invalid_argument with a
/// one-line message "SOURCE: volumes[N].FIELD: expected ..., found ...".
std::vector<CutVolume> parse_cut_volumes_json(const std::string& text, const std::filesystem::path& base_dir,
                                              const std::string& source);

/// The volumes of the JSON file at `path` (its size checked against `memory_limit_bytes` first).
/// Throws std::invalid_argument naming the file for an unreadable file or bad content.
std::vector<CutVolume> read_cut_volumes_file(const std::string& path, std::size_t memory_limit_bytes);

/// One volume as an entry of the format above (mesh files as they are stored in the volume).
nlohmann::json volume_json(const CutVolume& volume);

/// {"volumes": [...]}, mesh files made absolute so the file reads back from any folder.
nlohmann::json cut_volumes_document(const std::vector<CutVolume>& volumes);

}  // namespace cutaway::volumes

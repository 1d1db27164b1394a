#pragma once
// Cut volumes the user authors (issue 45): solids in the model's coordinates (x east, y north,
// z depth as the file stores it, the units `inspect --json` reports its bounds in) that enter the
// cut depth image beside the primaries' frustums. Kept GL-free: parsed from `--cut-volume SPEC`
// or a `--cut-volumes FILE.json`, turned into closed triangle meshes (volume_mesh.h), drawn by
// the pipeline's volume_cut pass.
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "grid/point3.h"
#include "shapes/tube_mesh.h"

namespace cutaway::volumes {

/// `box:X0,Y0,Z0,X1,Y1,Z1`: an axis-aligned box between two opposite corners (any order; stored
/// with min <= max on every axis).
struct BoxVolume {
    grid::Point3 min;
    grid::Point3 max;
};

/// `cylinder:X0,Y0,Z0,X1,Y1,Z1,R`: the segment from `from` to `to` and its radius R > 0.
struct CylinderVolume {
    grid::Point3 from;
    grid::Point3 to;
    double radius = 0;
};

/// `well:NAME[,R]`: a tube of radius R around the named well's path (without R: the caller's
/// default, volume_mesh.h).
struct WellVolume {
    std::string name;
    std::optional<double> radius;
};

/// `mesh:FILE`: a closed triangle mesh read from a PLY or OBJ file (mesh_file.h). `file` as the
/// user wrote it on the command line, or resolved against the JSON file's folder.
struct MeshVolume {
    std::string file;
};

using CutVolume = std::variant<BoxVolume, CylinderVolume, WellVolume, MeshVolume>;

/// "box", "cylinder", "well" or "mesh".
const char* kind_name(const CutVolume& volume);

/// The volume as a `--cut-volume` SPEC (numbers with 17 significant digits: parsed back, the same
/// doubles).
std::string spec_text(const CutVolume& volume);

/// Throws std::invalid_argument naming the field when the volume encloses nothing or cannot be
/// built: a box of zero extent on an axis, a cylinder of zero length, a radius that is not finite
/// and positive, a number that is not finite, an empty well name or
/// mesh file. The message has no prefix: the caller names the option or file.
void check_volume(const CutVolume& volume);

/// Sides of a cylinder's or well's cross-section: the drawn tubes' (shapes::tube_sides).
inline constexpr int tube_sides = shapes::tube_sides;

}  // namespace cutaway::volumes

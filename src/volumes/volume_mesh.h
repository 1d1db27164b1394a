#pragma once
// Cut volumes (cut_volume.h) as closed triangle meshes in the model's coordinates, what the
// pipeline's volume_cut pass draws.
#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "shapes/triangle_mesh.h"
#include "volumes/cut_volume.h"

namespace cutaway::volumes {

/// Well paths by name, model coordinates (x, y, z as the grid's corners: z depth), from the
/// wellhead down through the connected cells: what `well:NAME[,R]` cuts around. The caller fills
/// it from the model's wells (empty: the model has none, and every `well:` volume is refused).
using WellPaths = std::map<std::string, std::vector<grid::Point3>>;

struct VolumeBuildContext {
    const WellPaths* wells = nullptr;    ///< null: no wells
    double default_well_radius = 0;      ///< model units, for `well:NAME` without R (> 0)
    std::size_t memory_limit_bytes = 0;  ///< what reading a mesh file may use (mesh_file.h)
};

/// The radius `well:NAME` gets without R: 2% of the model's larger horizontal extent (a few cells
/// across on the presets), so the cut opens a shaft around the well at any model size.
double default_well_radius(const grid::Box3& model_bounds);

/// The closed mesh of `volume`. Throws std::invalid_argument with a one-line message naming the
/// volume's spec: an unknown well ("unknown well NAME (the model has no wells)" or naming the
/// model's wells), a mesh file that is missing, too large, open or non-manifold.
shapes::TriangleMesh build_volume_mesh(const CutVolume& volume, const VolumeBuildContext& context);

/// An axis-aligned box between `min` and `max` as 12 triangles (24 positions: one normal per face).
shapes::TriangleMesh box_mesh(const grid::Point3& min, const grid::Point3& max);

}  // namespace cutaway::volumes

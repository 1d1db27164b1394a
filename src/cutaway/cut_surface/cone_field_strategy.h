#pragma once
// The cone-field cut strategies (SPEC section 2, "Alternative cut surfaces"): seeds rendered on
// the GPU (cut_seeds.h), the cut d(p) = max over seeds q of (z(q) - m |q - p|) computed
//   - on the GPU for chamfer and jump flooding (gpu_cone_transform.h), nothing read back;
//   - on the CPU for the exact reference (seeds read back, result uploaded: readback_bytes).
// Each strategy file only names its mask or variant; everything else is here. The CPU functions
// of cone_field/ stay as the references the GPU transforms are tested against.
//
// Cone slope m (depth units per pixel): cone_slope_per_pixel with
//   - the HORIZONTAL wall angle only (half the full aperture; the cones are round, the vertical
//     aperture is ignored), its tangent clamped to [1e-4, 1e4] as the frustum union clamps its
//     walls (aperture 0: cones steeper than any depth step, i.e. the seeds alone; 180: nearly
//     flat). The cone leans out by that angle from the view AXIS, where the frustum walls lean
//     from each edge's view ray (frustum.geom): the two agree for primaries near the image centre;
//   - the reference depth s = inputs.cone_reference_depth, the depth of the primaries' centroid
//     (known on the CPU, so the slope needs no read-back): one pixel spans s / focal_px eye units
//     at depth s, so cones of seeds far from that depth open slightly wider or narrower than the
//     frustum walls would (a straight cone in screen space approximates a perspective one).
#include <functional>
#include <string>

#include "cone_field/chamfer.h"
#include "cone_field/cone_image.h"
#include "cone_field/jump_flooding.h"
#include "cutaway/cut_surface/cut_surface_strategy.h"

namespace cutaway::pipeline {

/// The slope m of the seeds' cones for `inputs` (see above), depth units per pixel.
double cut_cone_slope(const CutSurfaceInputs& inputs);

/// The cut of `seeds` by `cut` with cut_cone_slope, as stored: depth s, 0 at or in front of the
/// near plane (storable_cut_depth). All zero without seeds.
cone_field::FloatImage cone_field_cut_for(const CutSurfaceInputs& inputs, const cone_field::SeedImage& seeds,
                                          const ConeFieldCut& cut);

/// A registry entry running `cut` on the CPU; `why` says why it runs there.
CutSurfaceEntry cone_field_entry(std::string name, std::string why, ConeFieldCut cut);

/// Chamfer propagation with `mask`, on the GPU.
CutSurfaceEntry chamfer_entry(std::string name, cone_field::ChamferMask mask);
/// Jump flooding with `variant`, on the GPU.
CutSurfaceEntry jump_flooding_entry(std::string name, cone_field::JfaVariant variant);

// One per file (chamfer_3x3.cpp, ...), listed in cut_surface_registry.cpp.
CutSurfaceEntry chamfer_3x3_entry();
CutSurfaceEntry chamfer_34_entry();
CutSurfaceEntry chamfer_5x5_entry();
CutSurfaceEntry jfa_entry();
CutSurfaceEntry jfa_plus_1_entry();
CutSurfaceEntry jfa_plus_2_entry();
CutSurfaceEntry one_plus_jfa_entry();
CutSurfaceEntry jfa_squared_entry();
CutSurfaceEntry exact_entry();
CutSurfaceEntry frustum_sweep_entry();

/// The exact cone field (exact_reference_cut), the reference of --exact-check (exact.cpp).
cone_field::FloatImage exact_cone_cut(const cone_field::SeedImage& seeds, double slope_per_pixel);

}  // namespace cutaway::pipeline

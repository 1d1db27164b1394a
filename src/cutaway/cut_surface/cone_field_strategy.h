#pragma once
// The cone-field cut strategies (SPEC section 2, "Alternative cut surfaces"): seeds from the GPU
// (cut_seeds.h), the cut d(p) = max over seeds q of (z(q) - m |q - p|) computed on the CPU by one
// of the cone_field functions, the result uploaded into CutTargets::depth. Each strategy file only
// names its cone_field function; everything else is here.
//
// Cone slope m (depth units per pixel): cone_slope_per_pixel with
//   - the HORIZONTAL aperture only (the cones are round; the vertical aperture is ignored),
//     its tangent clamped to [1e-4, 1e4] as the frustum union clamps its walls (0 degrees: cones
//     steeper than any depth step, i.e. the seeds alone; 90 degrees: nearly flat);
//   - the reference depth = the MEDIAN seed depth s: one pixel spans s / focal_px eye units at
//     depth s, so cones of seeds far from that depth open slightly wider or narrower than the
//     frustum walls would (a straight cone in screen space approximates a perspective one).
#include <functional>
#include <string>

#include "cutaway/cone_field/chamfer.h"
#include "cutaway/cone_field/cone_image.h"
#include "cutaway/cone_field/jump_flooding.h"
#include "cutaway/cut_surface/cut_surface_strategy.h"

namespace cutaway::pipeline {

/// A cone-field cut: seeds (depth units) and slope m (depth units per pixel) to the cut surface.
using ConeFieldCut = std::function<cone_field::FloatImage(const cone_field::SeedImage&, double slope_per_pixel)>;

/// The slope m of the seeds' cones for `inputs` (see above). Throws std::invalid_argument if
/// there is no seed.
double cut_cone_slope(const CutSurfaceInputs& inputs, const cone_field::SeedImage& seeds);

/// The cut of `seeds` by `cut` with cut_cone_slope, as stored: depth s, 0 at or in front of the
/// near plane (storable_cut_depth). All zero without seeds.
cone_field::FloatImage cone_field_cut_for(const CutSurfaceInputs& inputs, const cone_field::SeedImage& seeds,
                                          const ConeFieldCut& cut);

/// A registry entry running `cut` on the CPU; `why` says why it runs there.
CutSurfaceEntry cone_field_entry(std::string name, std::string why, ConeFieldCut cut);

/// Chamfer propagation with `mask`.
CutSurfaceEntry chamfer_entry(std::string name, cone_field::ChamferMask mask);
/// Jump flooding with `variant`.
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

/// The exact cone field (exact_reference_cut), the reference of --exact-check (exact.cpp).
cone_field::FloatImage exact_cone_cut(const cone_field::SeedImage& seeds, double slope_per_pixel);

}  // namespace cutaway::pipeline

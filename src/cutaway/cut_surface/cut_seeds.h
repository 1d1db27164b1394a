#pragma once
// Seeds of the cone-field cut strategies (SPEC section 2): the primaries' rear hull, "from cell
// boxes" or "from cell geometry" (inputs.seeds). Geometry: the primaries' own faces, drawn with
// the same inverted depth test, so each covered pixel holds the depth of the cluster's rear face
// there, which is behind every primary fragment of that pixel (widened by one pixel afterwards,
// see cut_seeds.cpp). Boxes: each primary cell's box back face (the frustum without its walls:
// the largest depth s of the box, pushed back by the margin, over its (u, v) footprint widened by
// one pixel) is rasterised with an inverted depth test. Both run on the GPU; render() then reads
// the image back for the CPU transforms. Every pixel a primary covers
// thus holds a seed at least as deep as that primary, so any cut d(p) >= seed(p) keeps every
// primary pixel exposed, whatever the cone slope. Cells opening their cut (inputs.openings) add
// their box back faces part of the way from the rim (opening_cut.h).
#include "cone_field/cone_image.h"
#include "cutaway/cut_surface/cut_surface_strategy.h"
#include "gl/gl_objects.h"

namespace cutaway::pipeline {

class CutSeedPass {
public:
    explicit CutSeedPass(const gl::ShaderLibrary& shaders);

    /// Seeds at the cut camera's image size: depth s along its view axis (render units), row 0 at
    /// the top, cone_field::no_seed where no primary box was drawn.
    cone_field::SeedImage render(const CutSurfaceInputs& inputs);

    /// The seeds left on the GPU: a GL_DEPTH_COMPONENT32F texture of the cut camera's size (rows
    /// bottom to top) holding (s - near) / (far - near), 0 where no primary was drawn. Geometry
    /// seeds are NOT yet widened by a pixel here (needs_widening): the GPU transforms widen them
    /// in their first pass. Valid until the next call.
    const gl::Texture& render_on_gpu(const CutSurfaceInputs& inputs);
    static bool needs_widening(const CutSurfaceInputs& inputs) { return inputs.seeds == SeedSource::geometry; }

private:
    gl::Program program_;           ///< box back faces
    gl::Program geometry_program_;  ///< the primaries' faces
    gl::Texture depth_;          ///< resized with the camera
    gl::Framebuffer framebuffer_;
};

}  // namespace cutaway::pipeline

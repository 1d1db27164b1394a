#pragma once
// Seeds of the cone-field cut strategies (SPEC section 2): the primaries' rear hull, "from cell
// boxes" or "from cell geometry" (inputs.seeds). Geometry: the primaries' own faces, drawn with
// the same inverted depth test, so each covered pixel holds the depth of the cluster's rear face
// there, which is behind every primary fragment of that pixel. Boxes: Runs on the GPU: each primary cell's box back face (the frustum without its walls: the
// largest depth s of the box, pushed back by the margin, over its (u, v) footprint widened by one
// pixel) is rasterised with an inverted depth test, then read back. Every pixel a primary covers
// thus holds a seed at least as deep as that primary, so any cut d(p) >= seed(p) keeps every
// primary pixel exposed, whatever the cone slope.
#include "cutaway/cone_field/cone_image.h"
#include "cutaway/cut_surface/cut_surface_strategy.h"
#include "gl/gl_objects.h"

namespace cutaway::pipeline {

class CutSeedPass {
public:
    explicit CutSeedPass(const gl::ShaderLibrary& shaders);

    /// Seeds at the cut camera's image size: depth s along its view axis (render units), row 0 at
    /// the top, cone_field::no_seed where no primary box was drawn.
    cone_field::SeedImage render(const CutSurfaceInputs& inputs);

private:
    gl::Program program_;           ///< box back faces
    gl::Program geometry_program_;  ///< the primaries' faces
    gl::Texture depth_;          ///< resized with the camera
    gl::Framebuffer framebuffer_;
};

}  // namespace cutaway::pipeline

#pragma once
// The primaries' centroid (render-space mean of their cell centres, each the mean of its 8
// corners) computed on the GPU from the selection's primary cell list and the uploaded geometry:
// the renderer needs no CPU corner depths after set-up (render frees them: 32 bytes per cell).
// Partial sums of 256 cells in float on the GPU, added in double on the CPU (16 bytes read back
// per 256 primaries, once per selection).
#include <glm/glm.hpp>

#include "cutaway/grid_buffers.h"
#include "gl/gl_objects.h"
#include "gl/shader_library.h"

namespace cutaway::pipeline {

class PrimaryCentroid {
public:
    explicit PrimaryCentroid(const gl::ShaderLibrary& shaders);
    /// The centroid of `grid`'s current primary cells (GridBuffers::primary_cells); the origin without any.
    glm::vec3 compute(const GridBuffers& grid);

private:
    gl::Program program_;
    gl::Buffer partial_sums_;  ///< one vec4 per workgroup, grown as needed
};

}  // namespace cutaway::pipeline

#pragma once
// The primaries' centroid (render-space mean of their cell centres, each the mean of its 8
// corners) summed on the GPU from the selection's primary cell list and the uploaded geometry:
// the renderer needs no CPU corner depths after set-up (render frees them: 32 bytes per cell).
// Partial sums of 256 cells in float on the GPU, added in double on the CPU (16 bytes read back
// per 256 primaries, once per selection).
#include <cstdint>

#include <glm/glm.hpp>

#include "cutaway/grid_buffers.h"
#include "gl/gl_objects.h"
#include "gl/shader_library.h"

namespace cutaway::pipeline {

/// Sum of the render-space centres of a set of primary cells, and their count (renderers that
/// each draw one block of a model add theirs before dividing).
struct CentreSum {
    glm::dvec3 sum{0};
    std::uint64_t count = 0;
};

class PrimaryCentroid {
public:
    explicit PrimaryCentroid(const gl::ShaderLibrary& shaders);
    /// The sum of the centres of `grid`'s current primary cells (GridBuffers::primary_cells).
    CentreSum centre_sum(const GridBuffers& grid);

private:
    gl::Program program_;
    gl::Buffer partial_sums_;  ///< one vec4 per workgroup, grown as needed
};

}  // namespace cutaway::pipeline

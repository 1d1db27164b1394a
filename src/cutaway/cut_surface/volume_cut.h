#pragma once
// Cut volumes the user authors (issue 45) as a stage 1 input: their triangles, uploaded once per
// volume set in render space, drawn into the cut's depth image after the primaries' cut with the
// same max (GL_GREATER), so everything downstream (strategies' resolve, mean filter, borders,
// culling, metrics, freeze view, the distributed max) reads one cut and never knows where it came
// from. shaders/cut_surface/volume.{vert,geom,frag} say what one triangle removes.
#include <cstddef>
#include <vector>

#include "cutaway/cut_surface/cut_surface_strategy.h"
#include "cutaway/frame_targets.h"
#include "cutaway/model_frame.h"
#include "gl/gl_objects.h"
#include "gl/shader_library.h"
#include "shapes/triangle_mesh.h"

namespace cutaway::pipeline {

class VolumeCut {
public:
    explicit VolumeCut(const gl::ShaderLibrary& shaders);

    /// Replaces the volumes by `meshes` (closed, model coordinates), converted to render space by
    /// `frame`; an empty list removes them.
    void set_volumes(const std::vector<shapes::TriangleMesh>& meshes, const ModelFrame& frame);
    bool empty() const { return triangles_ == 0; }
    std::size_t triangle_count() const { return triangles_; }
    std::size_t memory_bytes() const { return positions_.size_bytes(); }

    /// Draws the volumes' cut into targets' depth (already holding the primaries' cut, or cleared):
    /// GL_GREATER with depth clamp; leaves the depth function at GL_LESS and depth clamp off.
    void draw(const CutSurfaceInputs& inputs, const CutTargets& targets) const;

private:
    gl::Program program_;
    gl::Buffer positions_;  ///< 6 per triangle (corners and the vertices across its edges), render space, float x y z
    gl::VertexArray vertex_array_;
    std::size_t triangles_ = 0;
    float outward_sign_ = 1;  ///< -1 when the model-to-render map mirrors (triangles then wound inward)
};

}  // namespace cutaway::pipeline

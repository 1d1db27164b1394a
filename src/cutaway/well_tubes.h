#pragma once
// Stage 3's well tubes: each well's path as a closed tube (shapes::tube_mesh) in render space,
// uploaded once per well set, drawn into the scene's G-buffer after the primaries and never cut
// (common/shared_constants.h flag_well: no cell, the well's index in the flags).
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "cutaway/camera.h"
#include "cutaway/camera_blocks.h"
#include "cutaway/model_frame.h"
#include "gl/gl_objects.h"
#include "gl/shader_library.h"
#include "grid/point3.h"

namespace cutaway::pipeline {

/// A well as the renderer draws it.
struct DrawnWell {
    std::string name;
    std::vector<grid::Point3> path;  ///< model units, from the wellhead down (wells::well_path)
    glm::vec3 colour{1.0f};          ///< linear RGB (wells::well_colour)
};

/// The wells of a frame and their tubes' radius (model units, horizontal: the tubes are built in
/// render space, so the vertical exaggeration does not flatten them).
struct WellSet {
    std::vector<DrawnWell> wells;
    double radius = 0;
};

/// Sets `frame.drawn_with` to the wellheads of `wells` (each path's first point, render space), so
/// that a framed camera shows every well drawn whole with the model. A frame that changes its
/// wells (an animation where a well is drilled) may so change its framing.
void keep_wellheads_in_view(ModelFrame& frame, const WellSet& wells);

/// A wellhead as the labels need it: the well's name, colour and its path's first point (render space).
struct WellHead {
    std::string name;
    glm::vec3 colour{1.0f};
    glm::vec3 position{0.0f};  ///< render space, the path's first point (above the model)
    glm::vec3 next{0.0f};      ///< the path's second point: a label's anchor slides down to it when the head is out of view
};

class WellTubes {
public:
    explicit WellTubes(const gl::ShaderLibrary& shaders);
    /// Builds the tubes of `set` in `frame`'s render space and uploads them (replacing the last
    /// set). Throws std::invalid_argument for more than max_drawn_wells wells, a path of fewer
    /// than two distinct points or a radius that is not positive.
    void set(const WellSet& set, const ModelFrame& frame);
    bool empty() const { return index_count_ == 0; }
    std::size_t triangle_count() const { return std::size_t(index_count_) / 3; }
    std::size_t memory_bytes() const;
    const std::vector<WellHead>& heads() const { return heads_; }
    /// Draws into the bound scene framebuffer with its depth test, seen from `camera` (bound by `cameras`).
    void draw(const Camera& camera, const CameraBlocks& cameras) const;

private:
    gl::Program program_;
    gl::VertexArray vertex_array_;
    gl::Buffer vertices_;
    gl::Buffer indices_;
    GLsizei index_count_ = 0;
    std::vector<WellHead> heads_;
};

}  // namespace cutaway::pipeline

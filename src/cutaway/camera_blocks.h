#pragma once
// The per-frame cameras as two std140 uniform blocks (shaders/common/cameras.glsl), bound at
// shared::ubo_view_camera and shared::ubo_cut_camera: ViewCamera, the camera a pass rasterises with
// (the model camera in stages 2 and 3 and the culling, the cut camera where a pass draws depths
// from it), and CutCamera, the camera whose cut image stage 2 and the culling read. A block is
// uploaded only when a different camera is bound to it: once per frame each while the view is not
// frozen, instead of a dozen uniforms set by name on every program that draws.
#include "cutaway/camera.h"
#include "gl/gl_objects.h"

namespace cutaway::pipeline {

/// ViewCamera's std140 layout (a vec3 followed by a float shares one 16-byte slot).
struct ViewCameraBlock {
    glm::mat4 view_projection{1}, view{1}, inverse_view{1}, inverse_view_projection{1};
    glm::vec3 eye{0};
    float focal_px = 0;
    glm::vec2 viewport_size{0}, projection_scale{0};
    float near_plane = 0, far_plane = 0;
    float padding[2] = {0, 0};
    static ViewCameraBlock of(const Camera& camera);
};

/// CutCamera's std140 layout (an array of vec3 has a 16-byte stride: vec4 here).
struct CutCameraBlock {
    glm::mat4 view{1}, projection{1}, view_projection{1};
    glm::vec3 ray_origin{0};
    float near_plane = 0;
    glm::vec4 ray_per_px[2] = {glm::vec4(0), glm::vec4(0)};
    glm::vec2 size{0};
    float far_plane = 0;
    float padding = 0;
    static CutCameraBlock of(const Camera& cut_camera);
};

class CameraBlocks {
public:
    CameraBlocks();
    /// Binds `camera` as the camera the next passes rasterise with (uploaded if it changed).
    void bind_view(const Camera& camera) const;
    /// Binds `cut_camera` as the camera whose cut image the next passes read.
    void bind_cut(const Camera& cut_camera) const;

private:
    gl::Buffer view_, cut_;
    // What each buffer holds: the GPU's copy, compared before an upload.
    mutable ViewCameraBlock view_held_;
    mutable CutCameraBlock cut_held_;
    mutable bool view_uploaded_ = false, cut_uploaded_ = false;
};

}  // namespace cutaway::pipeline

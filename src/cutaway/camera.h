#pragma once
// Perspective orbit camera around the model's centre (render space, Z up).
#include <glm/glm.hpp>

#include "cutaway/model_frame.h"

namespace cutaway::pipeline {

struct OrbitPose {
    float azimuth_deg = 35;    ///< around +Z, 0 = looking along +Y (from the south)
    float elevation_deg = 30;  ///< above the horizontal
    float distance = 0;        ///< render units from the centre; 0 frames the whole model
    glm::vec3 target{0};       ///< orbit centre (pan), render space
};

struct Camera {
    glm::mat4 view{1};
    glm::mat4 projection{1};
    glm::vec3 eye{0};
    float near_plane = 0.1f;
    float far_plane = 1.0f;
    float fovy_rad = 0;
    int width = 1;
    int height = 1;

    glm::mat4 view_projection() const { return projection * view; }
    /// Focal length in pixels: one eye-space unit at distance 1 spans this many pixels.
    float focal_px() const;
};

/// Whether `a` and `b` see the same image (the cut was made from the model camera, the view not
/// frozen): the shaders' CUT_CAMERA_IS_VIEW variants then take a point's cut texel and depth
/// from its own projection.
inline bool same_view(const Camera& a, const Camera& b) {
    return a.view == b.view && a.projection == b.projection && a.width == b.width && a.height == b.height;
}

/// Vertical field of view of every frame (degrees).
inline constexpr float default_fovy_deg = 30.0f;

/// Share of the free image width or height (the tighter one) that a framed model fills: issue 15
/// asks for at least 85% of the panel. Measured on the model's outline (ModelFrame::outline), so
/// a domed top or an inactive corner does not leave an empty margin as the bounding box would.
inline constexpr float framed_fill = 0.97f;

/// Camera of `pose` for a `width` x `height` image; near/far planes hug the model's bounding sphere.
/// With `pose.distance` 0 the camera is framed: moved along the view direction and panned so that
/// the model's projected outline (and what is drawn with it: ModelFrame::drawn_with) fills
/// `framed_fill` of the image left of its `reserved_right_px` rightmost columns (kept for the
/// colour bar) and `reserved_left_px` leftmost ones (the viewer's control panel), and below its
/// `reserved_top_px` top rows (a report step's caption), centred there.
Camera make_orbit_camera(const ModelFrame& frame, const OrbitPose& pose, int width, int height,
                         float reserved_right_px = 0, float reserved_left_px = 0, float reserved_top_px = 0);

}  // namespace cutaway::pipeline

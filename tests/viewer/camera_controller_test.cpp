// Camera moves: orbit wrap and clamp, zoom and pan checked against make_orbit_camera.
#include <gtest/gtest.h>

#include <stdexcept>

#include "cutaway/model_frame.h"
#include "grid/box_grid.h"
#include "viewer/camera_controller.h"

namespace cutaway::viewer {
namespace {

using pipeline::Camera;
using pipeline::OrbitPose;

constexpr int image_width = 800, image_height = 600;

pipeline::ModelFrame box_frame() {
    grid::BoxGridSpec spec;
    spec.dims = {4, 3, 2};
    return pipeline::make_model_frame(grid::make_box_grid(spec), 1.0);
}

/// Pixel position of render-space point `p` (x right, y up, origin at the image's bottom-left corner).
glm::vec2 project_to_pixels(const Camera& camera, const glm::vec3& p) {
    const glm::vec4 clip = camera.view_projection() * glm::vec4(p, 1);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return (ndc * 0.5f + 0.5f) * glm::vec2(float(camera.width), float(camera.height));
}

TEST(CameraController, OrbitWrapsAzimuthAndClampsElevation) {
    OrbitPose pose;
    pose.azimuth_deg = 350;
    pose.elevation_deg = 80;
    orbit(pose, 20, 20);
    EXPECT_FLOAT_EQ(pose.azimuth_deg, 10);
    EXPECT_FLOAT_EQ(pose.elevation_deg, 89);
    orbit(pose, -30, -200);
    EXPECT_FLOAT_EQ(pose.azimuth_deg, 340);
    EXPECT_FLOAT_EQ(pose.elevation_deg, -89);
    orbit(pose, 20, 0);  // exactly 360 wraps to 0
    EXPECT_FLOAT_EQ(pose.azimuth_deg, 0);
    orbit(pose, -720.5f, 0);
    EXPECT_FLOAT_EQ(pose.azimuth_deg, 359.5f);
}

TEST(CameraController, ZoomFromAFramedPoseScalesTheFramedDistance) {
    const pipeline::ModelFrame frame = box_frame();
    OrbitPose pose;  // distance 0: framed
    const Camera framed = pipeline::make_orbit_camera(frame, pose, image_width, image_height);
    const float framed_distance = glm::length(framed.eye - pose.target);
    zoom(pose, framed, 2.0f);
    const Camera zoomed = pipeline::make_orbit_camera(frame, pose, image_width, image_height);
    // Relative 1e-5: a few float roundings of a length of a few hundred units.
    EXPECT_NEAR(glm::length(zoomed.eye - pose.target), 2 * framed_distance, 1e-5f * framed_distance);
}

TEST(CameraController, ZoomRefusesBadFactors) {
    OrbitPose pose;
    const Camera camera = pipeline::make_orbit_camera(box_frame(), pose, image_width, image_height);
    EXPECT_THROW(zoom(pose, camera, 0.0f), std::invalid_argument);
    EXPECT_THROW(zoom(pose, camera, -1.0f), std::invalid_argument);
    EXPECT_THROW(zoom(pose, camera, NAN), std::invalid_argument);
    EXPECT_THROW(zoom(pose, camera, INFINITY), std::invalid_argument);
}

TEST(CameraController, PanMovesTheOldTargetByTheRequestedImageHeights) {
    const pipeline::ModelFrame frame = box_frame();
    OrbitPose pose;
    pose.azimuth_deg = 120;
    pose.elevation_deg = -25;
    pose.distance = 900;
    pose.target = {10, -20, 5};
    const glm::vec3 old_target = pose.target;
    const Camera before = pipeline::make_orbit_camera(frame, pose, image_width, image_height);
    const float dx = 0.1f, dy = -0.2f;
    pan(pose, before, dx, dy);
    const Camera after = pipeline::make_orbit_camera(frame, pose, image_width, image_height);
    const glm::vec2 expected = glm::vec2(image_width, image_height) * 0.5f + glm::vec2(dx, dy) * float(image_height);
    const glm::vec2 landed = project_to_pixels(after, old_target);
    // 0.01 px: float error of a projection at ~1000 units from the eye is far below a pixel.
    EXPECT_NEAR(landed.x, expected.x, 0.01f);
    EXPECT_NEAR(landed.y, expected.y, 0.01f);
    EXPECT_FLOAT_EQ(pose.distance, 900);
}

TEST(CameraController, PanOnAFramedPoseKeepsTheFramedDistance) {
    const pipeline::ModelFrame frame = box_frame();
    OrbitPose pose;  // distance 0: framed
    const Camera framed = pipeline::make_orbit_camera(frame, pose, image_width, image_height);
    pan(pose, framed, 0.25f, 0.0f);
    // Relative 1e-5: the length of eye - target rounds a few times in float.
    const float framed_distance = glm::length(framed.eye - glm::vec3(0));
    EXPECT_NEAR(pose.distance, framed_distance, 1e-5f * framed_distance);
}

TEST(CameraController, DragOfOneImageHeightIsHalfATurn) {
    EXPECT_FLOAT_EQ(drag_degrees(600, 600), 180);
    EXPECT_FLOAT_EQ(drag_degrees(-150, 600), -45);
}

}  // namespace
}  // namespace cutaway::viewer

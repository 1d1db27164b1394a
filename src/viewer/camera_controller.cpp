#include "viewer/camera_controller.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace cutaway::viewer {

namespace {

constexpr float max_elevation_deg = 89.0f;  // the same clamp as make_orbit_camera: the view's up is +Z

float eye_distance(const pipeline::OrbitPose& pose, const pipeline::Camera& camera) {
    return glm::length(camera.eye - pose.target);
}

}  // namespace

void orbit(pipeline::OrbitPose& pose, float d_azimuth_deg, float d_elevation_deg) {
    float azimuth = std::fmod(pose.azimuth_deg + d_azimuth_deg, 360.0f);
    if (azimuth < 0) azimuth += 360.0f;
    if (azimuth >= 360.0f) azimuth = 0;  // -tiny + 360 rounds to 360
    pose.azimuth_deg = azimuth;
    pose.elevation_deg = std::clamp(pose.elevation_deg + d_elevation_deg, -max_elevation_deg, max_elevation_deg);
}

void zoom(pipeline::OrbitPose& pose, const pipeline::Camera& camera, float factor) {
    if (!std::isfinite(factor) || factor <= 0)
        throw std::invalid_argument("zoom factor " + std::to_string(factor) + "; expected a finite number > 0");
    pose.distance = eye_distance(pose, camera) * factor;
}

void pan(pipeline::OrbitPose& pose, const pipeline::Camera& camera, float dx, float dy) {
    const float distance = eye_distance(pose, camera);
    // The view matrix's rows are the camera's right, up and backward axes in render space.
    const glm::vec3 right{camera.view[0][0], camera.view[1][0], camera.view[2][0]};
    const glm::vec3 up{camera.view[0][1], camera.view[1][1], camera.view[2][1]};
    const float image_height = 2.0f * distance * std::tan(0.5f * camera.fovy_rad);  // render units at the target
    pose.target -= (right * dx + up * dy) * image_height;
    if (pose.distance <= 0) pose.distance = distance;
}

float drag_degrees(float pixels, int image_height) { return 180.0f * pixels / float(std::max(image_height, 1)); }

}  // namespace cutaway::viewer

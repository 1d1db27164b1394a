#include "cutaway/camera.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace cutaway::pipeline {

namespace {

/// Smallest distance along `direction` from `target` at which all 8 corners of the model's box
/// lie inside the view, plus 5% to spare.
float framing_distance(const ModelFrame& frame, const glm::vec3& target, const glm::vec3& direction, float fovy,
                       float aspect) {
    const glm::vec3 forward = -direction;
    const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0, 0, 1)));
    const glm::vec3 up = glm::cross(right, forward);
    const float tan_y = std::tan(0.5f * fovy), tan_x = tan_y * aspect;
    float distance = 0;
    for (int c = 0; c < 8; ++c) {
        const glm::vec3 corner{c & 1 ? frame.render_max.x : frame.render_min.x, c & 2 ? frame.render_max.y : frame.render_min.y,
                               c & 4 ? frame.render_max.z : frame.render_min.z};
        const glm::vec3 p = corner - target;
        const float along = glm::dot(p, forward);  // towards the far side
        distance = std::max({distance, std::abs(glm::dot(p, right)) / tan_x - along,
                             std::abs(glm::dot(p, up)) / tan_y - along});
    }
    return 1.05f * std::max(distance, 1e-3f * frame.radius());
}

}  // namespace

float Camera::focal_px() const { return 0.5f * float(height) / std::tan(0.5f * fovy_rad); }

Camera make_orbit_camera(const ModelFrame& frame, const OrbitPose& pose, int width, int height) {
    Camera camera;
    camera.width = width;
    camera.height = height;
    camera.fovy_rad = glm::radians(default_fovy_deg);
    const float aspect = float(width) / float(height);
    const float radius = std::max(frame.radius(), 1e-6f);
    const float azimuth = glm::radians(pose.azimuth_deg);
    const float elevation = glm::radians(std::clamp(pose.elevation_deg, -89.0f, 89.0f));
    const glm::vec3 direction{std::sin(azimuth) * std::cos(elevation), -std::cos(azimuth) * std::cos(elevation),
                              std::sin(elevation)};
    const float distance = pose.distance > 0 ? pose.distance : framing_distance(frame, pose.target, direction, camera.fovy_rad, aspect);
    camera.eye = pose.target + distance * direction;
    camera.view = glm::lookAt(camera.eye, pose.target, glm::vec3(0, 0, 1));
    const float centre_distance = glm::length(camera.eye);  // the model's centre is the origin
    camera.near_plane = std::max(centre_distance - 1.5f * radius, 1e-3f * centre_distance);
    camera.far_plane = centre_distance + 1.5f * radius;
    camera.projection = glm::perspective(camera.fovy_rad, aspect, camera.near_plane, camera.far_plane);
    return camera;
}

}  // namespace cutaway::pipeline

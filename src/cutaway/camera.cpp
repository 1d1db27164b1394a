#include "cutaway/camera.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

namespace cutaway::pipeline {

namespace {

/// Where a framed camera stands: `distance` along the view direction from `target + offset`,
/// `offset` perpendicular to the view direction (a pan that centres the model's image).
struct Framing {
    float distance = 0;
    glm::vec3 offset{0};
};

/// The bounds of the model's points as the camera of `framing` projects them: normalised device
/// x and y, or nothing when a point lies behind (or nearly at) the eye.
struct ProjectedBox {
    glm::vec2 min{0}, max{0};
    bool in_front = true;
};

struct ViewAxes {
    glm::vec3 direction, forward, right, up;
    float tan_x, tan_y;
};

/// The points framing looks at: the model's outline, or its box's 8 corners.
std::vector<glm::vec3> framing_points(const ModelFrame& frame) {
    std::vector<glm::vec3> points = frame.outline;
    if (points.empty())
        for (int c = 0; c < 8; ++c)
            points.push_back({c & 1 ? frame.render_max.x : frame.render_min.x, c & 2 ? frame.render_max.y : frame.render_min.y,
                              c & 4 ? frame.render_max.z : frame.render_min.z});
    points.insert(points.end(), frame.drawn_with.begin(), frame.drawn_with.end());
    return points;
}

ProjectedBox project_box(const std::vector<glm::vec3>& points, float radius, const glm::vec3& target, const ViewAxes& axes,
                         const Framing& framing) {
    const glm::vec3 eye = target + framing.offset + framing.distance * axes.direction;
    ProjectedBox box{glm::vec2(1e30f), glm::vec2(-1e30f), true};
    for (const glm::vec3& point : points) {
        const glm::vec3 p = point - eye;
        const float depth = glm::dot(p, axes.forward);
        if (depth < 1e-3f * radius) return {glm::vec2(0), glm::vec2(0), false};
        const glm::vec2 ndc{glm::dot(p, axes.right) / (depth * axes.tan_x), glm::dot(p, axes.up) / (depth * axes.tan_y)};
        box.min = glm::min(box.min, ndc);
        box.max = glm::max(box.max, ndc);
    }
    return box;
}

/// The image's free area in normalised device coordinates: [x0, x1] x [y0, y1].
struct FreeArea {
    glm::vec2 min{-1.0f}, max{1.0f};
};

/// Share of the free area that the projected box fills in its tighter dimension, after panning so
/// that its centre sits at the free area's centre (`framing.offset` is updated). Infinite when a
/// point is behind the eye.
float centred_fill(const std::vector<glm::vec3>& points, float radius, const glm::vec3& target, const ViewAxes& axes,
                   const FreeArea& free, Framing& framing) {
    const glm::vec2 free_centre = 0.5f * (free.min + free.max), free_size = free.max - free.min;
    ProjectedBox box;
    // The box's image moves by offset / depth: a few steps converge (depth differs little
    // across the box at a framing distance).
    for (int step = 0; step < 6; ++step) {
        box = project_box(points, radius, target, axes, framing);
        if (!box.in_front) return INFINITY;
        const glm::vec2 error = 0.5f * (box.min + box.max) - free_centre;
        framing.offset += axes.right * (error.x * framing.distance * axes.tan_x) + axes.up * (error.y * framing.distance * axes.tan_y);
    }
    const glm::vec2 size = box.max - box.min;
    return std::max(size.x / free_size.x, size.y / free_size.y);
}

/// The distance (bisected on a log scale) and pan at which the model's projected points fill
/// `fill` of the free area in its tighter dimension, centred in it.
Framing frame_model(const ModelFrame& frame, const glm::vec3& target, const ViewAxes& axes, const FreeArea& free, float fill) {
    const float radius = std::max(frame.radius(), 1e-6f);
    const std::vector<glm::vec3> points = framing_points(frame);
    float near = 0.5f * radius, far = 1e3f * radius / axes.tan_y;
    Framing framing{far, glm::vec3(0)};
    for (int step = 0; step < 48; ++step) {
        Framing trial{std::sqrt(near * far), framing.offset};
        if (centred_fill(points, radius, target, axes, free, trial) > fill) {
            near = trial.distance;
        } else {
            far = trial.distance;
            framing = trial;
        }
    }
    centred_fill(points, radius, target, axes, free, framing);  // the pan for the final distance
    return framing;
}

}  // namespace

float Camera::focal_px() const { return 0.5f * float(height) / std::tan(0.5f * fovy_rad); }

Camera make_orbit_camera(const ModelFrame& frame, const OrbitPose& pose, int width, int height, float reserved_right_px,
                         float reserved_left_px, float reserved_top_px) {
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
    Framing framing{pose.distance, glm::vec3(0)};
    if (pose.distance <= 0) {
        ViewAxes axes{direction, -direction, {}, {}, 0, 0};
        axes.right = glm::normalize(glm::cross(axes.forward, glm::vec3(0, 0, 1)));
        axes.up = glm::cross(axes.right, axes.forward);
        axes.tan_y = std::tan(0.5f * camera.fovy_rad);
        axes.tan_x = axes.tan_y * aspect;
        // Columns kept free at either side (the colour bar, the viewer's panel), the model framed
        // in at least the middle fifth of the image; rows at the top (a caption), at most a quarter.
        const float right = std::clamp(reserved_right_px / float(width), 0.0f, 0.5f);
        const float left = std::clamp(reserved_left_px / float(width), 0.0f, 0.8f - right);
        const float top = std::clamp(reserved_top_px / float(height), 0.0f, 0.25f);
        const FreeArea free{{2.0f * left - 1.0f, -1.0f}, {1.0f - 2.0f * right, 1.0f - 2.0f * top}};
        framing = frame_model(frame, pose.target, axes, free, framed_fill);
    }
    const glm::vec3 look_at = pose.target + framing.offset;
    camera.eye = look_at + framing.distance * direction;
    camera.view = glm::lookAt(camera.eye, look_at, glm::vec3(0, 0, 1));
    const float centre_distance = glm::length(camera.eye);  // the model's centre is the origin
    camera.near_plane = std::max(centre_distance - 1.5f * radius, 1e-3f * centre_distance);
    camera.far_plane = centre_distance + 1.5f * radius;
    camera.projection = glm::perspective(camera.fovy_rad, aspect, camera.near_plane, camera.far_plane);
    return camera;
}

}  // namespace cutaway::pipeline

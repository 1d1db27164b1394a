#include "volume/view_geometry.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace cutaway::volume {

ViewGeometry make_view(const CubeDims& dims, const RayCastSettings& settings) {
    ViewGeometry view;
    view.box = glm::vec3(float(dims.samples), float(dims.crosslines), float(dims.inlines));
    const double lateral = std::max(dims.inlines, dims.crosslines);
    view.time_scale = settings.time_scale > 0 ? settings.time_scale : lateral / double(dims.samples);
    const float ts = float(view.time_scale);

    // Columns: where each voxel axis goes in world (time -> -z, crossline -> y, inline -> x).
    glm::mat4 axes(0.0f);
    axes[0] = glm::vec4(0, 0, -ts, 0);
    axes[1] = glm::vec4(0, 1, 0, 0);
    axes[2] = glm::vec4(1, 0, 0, 0);
    axes[3] = glm::vec4(0, 0, 0, 1);
    view.voxel_to_world = axes * glm::translate(glm::mat4(1.0f), -0.5f * view.box);
    view.mirrored = glm::determinant(glm::mat3(view.voxel_to_world)) < 0;

    const glm::vec3 half_world(0.5f * float(dims.inlines), 0.5f * float(dims.crosslines), 0.5f * float(dims.samples) * ts);
    const double radius = glm::length(half_world);
    const double fov = glm::radians(settings.camera.fov_deg);
    const double aspect = double(settings.width) / settings.height;
    // The cube's bounding sphere fits the columns between the reserved ones (colour bar, time axis).
    const double free_share = 1.0 - double(settings.reserved_right_px + settings.reserved_left_px) / settings.width;
    const double fit_fov = 2 * std::atan(std::tan(fov / 2) * std::min(1.0, aspect * free_share));
    view.distance = settings.camera.distance > 0 ? settings.camera.distance : 1.05 * radius / std::sin(fit_fov / 2);
    const double az = glm::radians(settings.camera.azimuth_deg), el = glm::radians(settings.camera.elevation_deg);
    const glm::vec3 eye = float(view.distance) *
                          glm::vec3(float(std::cos(el) * std::cos(az)), float(std::cos(el) * std::sin(az)), float(std::sin(el)));
    const float near_plane = float(std::max(0.01 * view.distance, view.distance - radius * 1.01));
    const float far_plane = float(view.distance + radius * 1.01);
    const glm::mat4 world_to_view = glm::lookAt(eye, glm::vec3(0), glm::vec3(0, 0, 1));
    // Shifted so the cube's centre lands in the middle of the free columns (NDC x (left - right) / width).
    const glm::mat4 shift = glm::translate(
        glm::mat4(1.0f), glm::vec3((settings.reserved_left_px - settings.reserved_right_px) / float(settings.width), 0, 0));
    const glm::mat4 projection = shift * glm::perspective(float(fov), float(aspect), near_plane, far_plane);
    view.voxel_to_clip = projection * world_to_view * view.voxel_to_world;
    view.clip_to_voxel = glm::inverse(view.voxel_to_clip);
    view.eye_voxel = glm::vec3(glm::inverse(view.voxel_to_world) * glm::vec4(eye, 1));
    return view;
}

VoxelRay pixel_ray(const ViewGeometry& view, int x, int y, int width, int height) {
    const glm::vec2 ndc((float(x) + 0.5f) / float(width) * 2 - 1, (float(y) + 0.5f) / float(height) * 2 - 1);
    const glm::vec4 far_point = view.clip_to_voxel * glm::vec4(ndc, 1, 1);
    const glm::vec3 target = glm::vec3(far_point) / far_point.w;
    return {view.eye_voxel, glm::normalize(target - view.eye_voxel)};
}

}  // namespace cutaway::volume

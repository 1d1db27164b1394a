#pragma once
// Camera moves on an orbit pose, shared by the mouse handlers and the viewer script.
#include "cutaway/camera.h"

namespace cutaway::viewer {

/// Adds degrees to the pose; azimuth is wrapped into [0, 360), elevation clamped to [-89, 89].
void orbit(pipeline::OrbitPose& pose, float d_azimuth_deg, float d_elevation_deg);

/// Multiplies the current eye distance |camera.eye - pose.target| by `factor` and stores it in
/// pose.distance, so a framed pose (distance 0) zooms from its framed distance. `factor` must be
/// finite and > 0 (else std::invalid_argument). `camera`: make_orbit_camera of `pose`.
void zoom(pipeline::OrbitPose& pose, const pipeline::Camera& camera, float factor);

/// Shifts the view so the scene moves by (dx, dy) image heights right / up on screen: the target
/// moves by -(right*dx + up*dy) * 2 * d * tan(fovy/2), with d the current eye distance. A framed pose
/// (distance 0) gets distance d, so the framing does not jump after the pan.
/// `camera`: make_orbit_camera of `pose`.
void pan(pipeline::OrbitPose& pose, const pipeline::Camera& camera, float dx, float dy);

/// Mouse drag in pixels to orbit degrees: 180 degrees per image height (`image_height` in pixels).
float drag_degrees(float pixels, int image_height);

}  // namespace cutaway::viewer

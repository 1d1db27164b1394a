// The per-frame cameras as uniform blocks, filled once per camera and bound by
// src/cutaway/camera_blocks.h (its ViewCameraBlock and CutCameraBlock mirror these layouts).
#ifndef CUTAWAY_CAMERAS_GLSL
#define CUTAWAY_CAMERAS_GLSL
#include "common/shared_constants.h"

// The camera the pass rasterises with: the model camera in stages 2 and 3 and the culling; the cut
// camera where a pass draws depths from it (the rear shell, the seeds' geometry).
layout(std140, binding = ubo_view_camera) uniform ViewCamera {
    mat4 view_projection;
    mat4 model_view;               // view matrix
    mat4 inverse_view;
    mat4 inverse_view_projection;
    vec3 eye_position;             // render space; also the headlight (common/lighting.glsl)
    float focal_px;                // focal length, pixels
    vec2 viewport_size;            // pixels
    vec2 projection_scale;         // P[0][0], P[1][1]
    float near_plane;
    float far_plane;
};

// The camera whose cut image stage 2 and the culling read: the model camera unless the view is
// frozen. cut_ray_origin + w.x cut_ray_per_px[0] + w.y cut_ray_per_px[1] is its ray through window
// position w, scaled to unit depth along its axis, in world space (common/cut_lookup.glsl).
layout(std140, binding = ubo_cut_camera) uniform CutCamera {
    mat4 cut_view;
    mat4 cut_projection;
    mat4 cut_view_projection;
    vec3 cut_ray_origin;
    float cut_near;
    vec3 cut_ray_per_px[2];
    vec2 cut_size;                 // pixels
    float cut_far;
};
#endif

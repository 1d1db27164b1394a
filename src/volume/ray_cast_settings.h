#pragma once
// Everything one volume frame depends on, shared by the GPU and the CPU caster so their images
// can be compared pixel for pixel. Lengths are in voxels (one voxel = one sample spacing on every
// axis of the cube, before the display's time scale).
#include "volume/transfer_function.h"

namespace cutaway::volume {

/// Orbit camera around the cube's centre (world z up, time runs down).
struct CameraSettings {
    double azimuth_deg = 40;     ///< from the inline axis towards the crossline axis
    double elevation_deg = 25;   ///< above the horizontal
    double distance = 0;         ///< eye to centre, world units (voxels); 0 frames the whole cube
    double fov_deg = 30;         ///< vertical field of view
};

struct RayCastSettings {
    int width = 512;   ///< image size, pixels
    int height = 512;
    CameraSettings camera;
    /// Displayed length of one time sample relative to one trace spacing; 0 picks the scale that
    /// makes the time extent equal the larger lateral extent.
    double time_scale = 0;
    float step = 0.5f;                 ///< distance between samples along a ray, voxels (> 0)
    bool opacity_correction = true;    ///< alpha' = 1 - (1 - alpha)^step (tables are per 1-voxel step)
    bool jitter = true;                ///< start each ray at a per-pixel hash fraction of a step
    bool early_termination = true;     ///< stop a ray once its opacity reaches early_termination_alpha
    float early_termination_alpha = 0.99f;
    bool empty_space_skipping = true;  ///< step over min/max blocks the transfer function makes empty
    int block_size = 4;                ///< empty-space block edge, voxels (4 skipped most on the paper cube)
    Rgba background{0, 0, 0, 1};       ///< behind the volume
    bool colour_bar = true;            ///< transfer-function bar at the right edge, inline / crossline / time edges
    /// Image columns at the right kept for the colour bar: a framed cube (distance 0) is fitted and
    /// centred left of them (0..width/2).
    float reserved_right_px = 0;
    /// Image columns at the left kept for the time axis's values (0..width/4), as the right ones.
    float reserved_left_px = 0;
    /// Capitals of the annotations' text (colour bar, axis labels) at least this tall, pixels
    /// (0: 2% of the image height; 0..200).
    float text_height_px = 0;
};

/// Throws std::invalid_argument naming the first field out of range.
void validate(const RayCastSettings& settings);

}  // namespace cutaway::volume

#pragma once
// The paper's timing protocol (SPEC.md section 3): "the model is rotated in several orientations
// while the aperture changes". A fixed, named path so every run times the same frames.
#include <vector>

#include "cutaway/camera.h"

namespace cutaway::bench {

struct PathPose {
    pipeline::OrbitPose orbit;  ///< azimuth/elevation in degrees; distance 0 frames the model
    float aperture_deg = 60;    ///< horizontal = vertical aperture, full opening angle, degrees
};

/// `count` poses: azimuth steps of 360/count degrees, elevation alternating 25/45 degrees, the
/// full aperture rising linearly from 30 to 120 degrees (one pose: 30 degrees), i.e. each wall
/// leaning out 15 to 60 degrees.
inline std::vector<PathPose> camera_path(int count) {
    std::vector<PathPose> path;
    for (int k = 0; k < count; ++k) {
        PathPose pose;
        pose.orbit.azimuth_deg = 360.0f * float(k) / float(count);
        pose.orbit.elevation_deg = k % 2 ? 45.0f : 25.0f;
        pose.aperture_deg = count > 1 ? 30.0f + 90.0f * float(k) / float(count - 1) : 30.0f;
        path.push_back(pose);
    }
    return path;
}

}  // namespace cutaway::bench

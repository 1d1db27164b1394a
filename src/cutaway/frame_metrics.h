#pragma once
// The image metrics of one cutaway frame (stats.json), measured with extra untimed renders:
// primaries only (exposure), 180-degree aperture and no cut (context kept).
#include "cutaway/cutaway_renderer.h"
#include "metrics/image_metrics.h"

namespace cutaway::pipeline {

struct FrameMetrics {
    metrics::Exposure exposure;
    metrics::ContextKept context;
    metrics::LineWidth border_width;      ///< border lines of the cutaway frame
    std::size_t secondary_in_front = 0;   ///< secondary pixels nearer than the cut (must be 0)
};

/// Renders the variants and measures. Leaves the renderer holding the last variant's frame.
/// Freeze view is left out of the invariant (the cut is another camera's then).
FrameMetrics measure_frame(CutawayRenderer& renderer, const FrameSettings& settings, const Camera& camera);

/// Secondary pixels of the renderer's last frame whose depth lies in front of the cut by more
/// than `relative_tolerance` x depth. Only meaningful when the cut camera is the model camera.
std::size_t secondary_pixels_in_front_of_cut(const CutawayRenderer& renderer, double relative_tolerance);
/// The same, with the last frame's ids already read back.
std::size_t secondary_pixels_in_front_of_cut(const CutawayRenderer& renderer, const IdImage& ids,
                                             double relative_tolerance);

}  // namespace cutaway::pipeline

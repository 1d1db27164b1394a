#include "cutaway/frame_metrics.h"
#include "cutaway/renderer_readback.h"

namespace cutaway::pipeline {
namespace {

metrics::PixelIds view(const IdImage& ids) { return {ids.width, ids.height, ids.cell, ids.flags}; }

}  // namespace

std::size_t secondary_pixels_in_front_of_cut(const CutawayRenderer& renderer, double relative_tolerance) {
    return secondary_pixels_in_front_of_cut(renderer, pipeline::FrameReadback(renderer).read_ids(), relative_tolerance);
}

std::size_t secondary_pixels_in_front_of_cut(const CutawayRenderer& renderer, const IdImage& ids,
                                             double relative_tolerance) {
    const FloatImage scene = pipeline::FrameReadback(renderer).read_scene_depth();
    const FloatImage cut = pipeline::FrameReadback(renderer).read_cut_depth();
    std::size_t count = 0;
    for (std::size_t i = 0; i < ids.cell.size(); ++i) {
        if (ids.cell[i] == 0 || (ids.flags[i] & flag_primary)) continue;
        if (double(scene.values[i]) < double(cut.values[i]) * (1.0 - relative_tolerance)) ++count;
    }
    return count;
}

FrameMetrics measure_frame(CutawayRenderer& renderer, const FrameSettings& settings, const Camera& camera) {
    FrameMetrics result;
    FrameSettings plain = settings;
    plain.ssao = false;
    plain.colour_bar = false;
    renderer.render(plain, camera);
    const IdImage cutaway = pipeline::FrameReadback(renderer).read_ids();
    result.border_width = metrics::line_width(view(cutaway), flag_border);
    // Depth is compared in float32 on both sides; 1e-5 relative covers the rounding of
    // reconstructing eye depth from the interpolated world position (a few ulps).
    if (!renderer.status().frozen) result.secondary_in_front = secondary_pixels_in_front_of_cut(renderer, cutaway, 1e-5);
    const std::size_t kept = metrics::context_pixels(view(cutaway));

    FrameSettings primaries_only = plain;
    primaries_only.only = OnlyLayer::primaries;
    renderer.render(primaries_only, camera);
    const IdImage primaries = pipeline::FrameReadback(renderer).read_ids();
    result.exposure = metrics::primary_exposure(view(primaries), view(cutaway));

    FrameSettings wide = plain;
    set_aperture_180(wide);
    wide.mean_filter = 0;
    renderer.render(wide, camera);
    const std::size_t kept_180 = metrics::context_pixels(view(pipeline::FrameReadback(renderer).read_ids()));

    FrameSettings uncut = plain;
    uncut.cut_enabled = false;
    renderer.render(uncut, camera);
    const std::size_t kept_uncut = metrics::context_pixels(view(pipeline::FrameReadback(renderer).read_ids()));
    result.context = metrics::context_kept(kept, kept_180, kept_uncut);
    return result;
}

}  // namespace cutaway::pipeline

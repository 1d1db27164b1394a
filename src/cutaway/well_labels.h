#pragma once
// Each drawn well's name on the final image beside its wellhead (annotation::place_labels): a light
// box with the name in the well's colour and a leader line to the wellhead.
#include <string>
#include <vector>

#include "annotation/label_placement.h"
#include "cutaway/camera.h"
#include "cutaway/overlay_batch.h"
#include "cutaway/well_tubes.h"

namespace cutaway::pipeline {

/// Where `heads` project in `camera`'s image (pixels, y down from the top), and each label's box,
/// for the wellheads in front of the camera and inside the image; `reserved_right`: columns kept
/// for the colour bar; `min_text_px`: the labels' capitals at least this tall (the colour bar's);
/// `caption`: the frame caption's text, whose box the labels keep clear of (empty: none).
std::vector<annotation::PlacedLabel> well_label_layout(const std::vector<WellHead>& heads, const Camera& camera,
                                                       float reserved_right, float min_text_px = 0,
                                                       const std::string& caption = {});

class WellLabels {
public:
    explicit WellLabels(const gl::ShaderLibrary& shaders) : batch_(shaders) {}
    /// Draws the labels of well_label_layout onto `target`.
    void draw(const gl::Framebuffer& target, const std::vector<WellHead>& heads, const Camera& camera, float reserved_right,
              float min_text_px = 0, const std::string& caption = {});

private:
    OverlayBatch batch_;
};

}  // namespace cutaway::pipeline

// Well-name labels (annotation/label_placement): each inside the image, clear of the others, of
// their leader lines and of every other wellhead, so that a reader can tell which name is whose.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "annotation/label_placement.h"

namespace cutaway::annotation {
namespace {

bool contains(const PixelRect& r, float x, float y) { return x >= r.x0 && x <= r.x1 && y >= r.y0 && y <= r.y1; }

/// Whether the segment (a, b) enters `r`, by sampling it every tenth of a pixel (a test's own
/// reference, independent of the clipping the placement uses).
bool segment_enters(const PixelRect& r, float ax, float ay, float bx, float by) {
    const int samples = 10 * int(std::abs(bx - ax) + std::abs(by - ay)) + 2;
    for (int s = 0; s <= samples; ++s) {
        const float t = float(s) / float(samples);
        // Strictly inside: a leader may end on its own box's edge and touch nothing else's.
        const float x = ax + t * (bx - ax), y = ay + t * (by - ay);
        if (x > r.x0 + 0.05f && x < r.x1 - 0.05f && y > r.y0 + 0.05f && y < r.y1 - 0.05f) return true;
    }
    return false;
}

/// Six wellheads crowded in a corner of a 640 x 360 image, like a field's producers seen from afar.
std::vector<LabelRequest> crowded_wells() {
    return {{"PROD1", 520, 60}, {"PROD2", 540, 70}, {"PROD3", 530, 85}, {"PROD4", 560, 60}, {"INJ1", 100, 200}, {"INJ2", 110, 215}};
}

/// Every label inside the `width` x `height` image, covering no other wellhead, overlapping no other
/// label and crossed by no other label's leader.
void expect_clear(const std::vector<LabelRequest>& requests, const std::vector<PlacedLabel>& placed, float width, float height) {
    ASSERT_EQ(placed.size(), requests.size());
    for (std::size_t a = 0; a < placed.size(); ++a) {
        const PlacedLabel& label = placed[a];
        EXPECT_TRUE(label.box.x0 >= 0 && label.box.y0 >= 0 && label.box.x1 <= width && label.box.y1 <= height) << label.line.text;
        for (std::size_t r = 0; r < requests.size(); ++r) {
            if (r == label.request) continue;
            EXPECT_FALSE(contains(label.box, requests[r].anchor_x, requests[r].anchor_y))
                << label.line.text << " covers the wellhead of " << requests[r].text;
        }
        for (std::size_t b = 0; b < placed.size(); ++b) {
            if (a == b) continue;
            const PlacedLabel& other = placed[b];
            EXPECT_FALSE(label.box.overlaps(other.box)) << label.line.text << " overlaps " << other.line.text;
            const auto [ex, ey] = leader_end(other.box, other.anchor_x, other.anchor_y);
            EXPECT_FALSE(segment_enters(label.box, other.anchor_x, other.anchor_y, ex, ey))
                << "the leader of " << other.line.text << " crosses " << label.line.text;
        }
    }
}

TEST(LabelPlacement, LabelsClearOfEachOtherTheirLeadersAndEveryWellhead) {
    const std::vector<LabelRequest> requests = crowded_wells();
    expect_clear(requests, place_labels(requests, 640, 360, 0, 14), 640, 360);
}

TEST(LabelPlacement, WellheadsAlongTheTopEdgeGetClearLabels) {
    // A generated deck's producers seen from above (wells_waterflood.png, 1280x720, text 36 px): the
    // wellheads run along the image's top edge, where no label fits above or beside them. Placed one
    // after another, the first took the spot below its neighbour and PROD2's leader crossed PROD1's
    // name; a label moved again once all are placed finds the spots where none crosses another.
    const std::vector<LabelRequest> requests{{"INJ1", 53.9f, 239.2f},  {"INJ2", 265.2f, 290.6f}, {"INJ3", 402.2f, 314.4f},
                                             {"INJ4", 630.5f, 428.9f},  {"PROD1", 572.3f, 14.8f}, {"PROD2", 708.1f, 21.8f},
                                             {"PROD3", 831.0f, 59.2f}, {"PROD4", 927.3f, 110.9f}};
    expect_clear(requests, place_labels(requests, 1280, 720, 212, 36), 1280 - 212, 720);
}

TEST(LabelPlacement, LabelsKeepClearOfTheFrameCaption) {
    // Wellheads under an animation frame's caption at the top left, as on a generated deck's producers.
    const std::optional<PlacedLabel> caption = place_caption("SWAT  2030-01-14  (step 3 of 0-30)", 640, 360, 0, 14);
    ASSERT_TRUE(caption.has_value());
    const std::vector<LabelRequest> requests{{"PROD3", 150, caption->box.y1 + 4}, {"INJ4", 300, caption->box.y1 + 6},
                                             {"PROD1", 60, caption->box.y1 + 30}};
    const std::vector<PlacedLabel> placed = place_labels(requests, 640, 360, 0, 14, {caption->box});
    ASSERT_EQ(placed.size(), requests.size());
    for (const PlacedLabel& label : placed) EXPECT_FALSE(label.box.overlaps(caption->box)) << label.line.text << " under the caption";
}

TEST(LabelPlacement, LeaderEndsOnTheBoxNearestTheAnchor) {
    const PixelRect box{10, 20, 50, 30};
    EXPECT_EQ(leader_end(box, 0, 0), (std::array<float, 2>{10, 20}));
    EXPECT_EQ(leader_end(box, 30, 100), (std::array<float, 2>{30, 30}));
    EXPECT_EQ(leader_end(box, 30, 25), (std::array<float, 2>{30, 25}));  // an anchor inside: no leader
}

}  // namespace
}  // namespace cutaway::annotation

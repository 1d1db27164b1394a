// Cut volumes are exact (issue 45): with --primaries none, one box and aperture 0, over random
// cameras and boxes, no pixel shows a cell lying wholly inside the box, and every pixel away from
// the box's projected footprint shows the cell the uncut frame shows there.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "cutaway/cutaway_renderer.h"
#include "cutaway/renderer_readback.h"
#include "gl_test_support.h"
#include "grid/cell_geometry.h"
#include "volumes/volume_mesh.h"

namespace cutaway::test {
namespace {

using Vec2 = glm::dvec2;

bool inside(const grid::Point3& p, const grid::Point3& lo, const grid::Point3& hi) {
    return p.x > lo.x && p.x < hi.x && p.y > lo.y && p.y < hi.y && p.z > lo.z && p.z < hi.z;
}

/// Eclipse indices of the active cells whose 8 corners all lie inside the box.
std::vector<bool> cells_inside(const grid::CornerPointGrid& grid, const grid::Point3& lo, const grid::Point3& hi) {
    std::vector<bool> within(grid.cell_count(), false);
    const grid::GridDims d = grid.dims();
    for (int k = 0; k < d.nz; ++k)
        for (int j = 0; j < d.ny; ++j)
            for (int i = 0; i < d.nx; ++i) {
                const grid::CellCorners corners = grid::cell_corners(grid, i, j, k);
                within[std::size_t(i) + std::size_t(d.nx) * (std::size_t(j) + std::size_t(d.ny) * std::size_t(k))] =
                    std::all_of(corners.begin(), corners.end(), [&](const grid::Point3& c) { return inside(c, lo, hi); });
            }
    return within;
}

/// The box's 8 corners in pixels (x right, y up, as GL's rows), through the renderer's frame and camera.
std::vector<Vec2> projected_corners(const pipeline::ModelFrame& frame, const pipeline::Camera& camera,
                                    const grid::Point3& lo, const grid::Point3& hi) {
    std::vector<Vec2> points;
    for (int c = 0; c < 8; ++c) {
        const glm::vec3 p = frame.to_render({c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z});
        const glm::vec4 clip = camera.projection * camera.view * glm::vec4(p, 1.0f);
        points.push_back({(clip.x / clip.w * 0.5 + 0.5) * camera.width, (clip.y / clip.w * 0.5 + 0.5) * camera.height});
    }
    return points;
}

double cross(const Vec2& o, const Vec2& a, const Vec2& b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

/// Convex hull, counter-clockwise (Andrew's monotone chain).
std::vector<Vec2> convex_hull(std::vector<Vec2> points) {
    std::sort(points.begin(), points.end(), [](const Vec2& a, const Vec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    std::vector<Vec2> hull(2 * points.size());
    std::size_t n = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        while (n >= 2 && cross(hull[n - 2], hull[n - 1], points[i]) <= 0) --n;
        hull[n++] = points[i];
    }
    for (std::size_t i = points.size() - 1, lower = n + 1; i-- > 0;) {
        while (n >= lower && cross(hull[n - 2], hull[n - 1], points[i]) <= 0) --n;
        hull[n++] = points[i];
    }
    hull.resize(n - 1);
    return hull;
}

/// Signed distance from `p` to the convex polygon (negative inside).
double signed_distance(const std::vector<Vec2>& hull, const Vec2& p) {
    double outside = -1e30;
    for (std::size_t i = 0; i < hull.size(); ++i) {
        const Vec2 a = hull[i], b = hull[(i + 1) % hull.size()];
        const Vec2 edge = b - a;
        outside = std::max(outside, -cross(a, b, p) / glm::length(edge));  // distance beyond edge's line
    }
    return outside;
}

TEST(CutVolumeGl, BoxCutIsExactAtApertureZero) {
    const grid::CornerPointGrid& grid = petra();
    constexpr int width = 320, height = 240;
    const auto renderer = make_renderer(grid, width, height);
    renderer->select(std::vector<std::uint8_t>(grid.cell_count(), 0));
    const grid::Box3 bounds = grid::grid_bounds(grid);
    std::mt19937 random(45);
    std::uniform_real_distribution<double> size(0.25, 0.6), place(0, 1);
    pipeline::FrameSettings settings;
    settings.primaries = false;
    settings.aperture_h_deg = settings.aperture_v_deg = 0;
    settings.mean_filter = 0;  // the filter spreads the cut by design
    settings.ssao = false;
    settings.colour_bar = false;
    // The rear-shell clamp keeps the model's back faces by design, also where they lie inside the
    // box: see-through lets the cut end at the box's rear as the volume says.
    settings.see_through = true;
    pipeline::FrameSettings uncut = settings;
    uncut.cut_enabled = false;
    std::size_t cut_pixels = 0;
    for (int trial = 0; trial < 6; ++trial) {
        grid::Point3 lo, hi;
        double* l[3] = {&lo.x, &lo.y, &lo.z};
        double* h[3] = {&hi.x, &hi.y, &hi.z};
        const double b_lo[3] = {bounds.min.x, bounds.min.y, bounds.min.z}, b_hi[3] = {bounds.max.x, bounds.max.y, bounds.max.z};
        for (int axis = 0; axis < 3; ++axis) {
            const double extent = b_hi[axis] - b_lo[axis], side = size(random) * extent;
            *l[axis] = b_lo[axis] + place(random) * (extent - side);
            *h[axis] = *l[axis] + side;
        }
        renderer->set_cut_volumes({volumes::box_mesh(lo, hi)});
        const pipeline::Camera camera = pipeline::make_orbit_camera(renderer->frame(), random_pose(random), width, height, 0);
        renderer->render(uncut, camera);
        const std::vector<std::uint32_t> before = pipeline::FrameReadback(*renderer).read_eclipse_ids();
        renderer->render(settings, camera);
        const std::vector<std::uint32_t> after = pipeline::FrameReadback(*renderer).read_eclipse_ids();
        const std::vector<bool> within = cells_inside(grid, lo, hi);
        const std::vector<Vec2> hull = convex_hull(projected_corners(renderer->frame(), camera, lo, hi));
        std::size_t inside_shown = 0, changed_outside = 0;
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const std::size_t pixel = std::size_t(y) * width + std::size_t(x);
                if (after[pixel] != 0 && within[after[pixel] - 1]) ++inside_shown;
                // One pixel of slack: the GPU snaps the box's corners to its sub-pixel grid and
                // tests pixel centres, so a centre within a pixel of the hull's edge may fall on
                // either side of it; and the border line drawn where the cut meets a cell is one
                // pixel (--border-width 1) wide at the cut's edge.
                if (signed_distance(hull, {x + 0.5, y + 0.5}) > 1.0 && after[pixel] != before[pixel]) ++changed_outside;
                cut_pixels += after[pixel] != before[pixel];
            }
        EXPECT_EQ(inside_shown, 0u) << "trial " << trial;
        EXPECT_EQ(changed_outside, 0u) << "trial " << trial;
    }
    EXPECT_GT(cut_pixels, 0u);  // the boxes did cut something
}

TEST(CutVolumeGl, VolumesAndApertureOnlyEverCutMore) {
    // A wall leans out with the aperture: a wider aperture never keeps a pixel a narrower one cut.
    const grid::CornerPointGrid& grid = petra();
    constexpr int width = 200, height = 150;
    const auto renderer = make_renderer(grid, width, height);
    renderer->select(std::vector<std::uint8_t>(grid.cell_count(), 0));
    const grid::Box3 b = grid::grid_bounds(grid);
    const grid::Point3 centre{0.5 * (b.min.x + b.max.x), 0.5 * (b.min.y + b.max.y), 0.5 * (b.min.z + b.max.z)};
    const double r = 0.15 * (b.max.x - b.min.x);
    renderer->set_cut_volumes({volumes::box_mesh({centre.x - r, centre.y - r, b.min.z - 1}, {centre.x + r, centre.y + r, centre.z})});
    std::mt19937 random(7);
    const pipeline::Camera camera = pipeline::make_orbit_camera(renderer->frame(), random_pose(random), width, height, 0);
    pipeline::FrameSettings s;
    s.primaries = false;
    s.mean_filter = 0;
    s.ssao = false;
    s.colour_bar = false;
    std::size_t previous = 0;
    for (float aperture : {0.0f, 60.0f, 120.0f}) {
        s.aperture_h_deg = s.aperture_v_deg = aperture;
        renderer->render(s, camera);
        const std::vector<std::uint32_t> ids = pipeline::FrameReadback(*renderer).read_eclipse_ids();
        s.cut_enabled = false;
        renderer->render(s, camera);
        const std::vector<std::uint32_t> plain = pipeline::FrameReadback(*renderer).read_eclipse_ids();
        s.cut_enabled = true;
        std::size_t changed = 0;
        for (std::size_t i = 0; i < ids.size(); ++i) changed += ids[i] != plain[i];
        EXPECT_GT(changed, previous) << "aperture " << aperture;
        previous = changed;
    }
}

}  // namespace
}  // namespace cutaway::test

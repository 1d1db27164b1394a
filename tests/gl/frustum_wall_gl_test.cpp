// The frustum walls against their closed form (SPEC section 2, stage 1): one box primary, known
// apertures, the drawn cut depth compared pixel by pixel with the wall geometry documented in
// shaders/cut_surface/frustum.geom, and the wall's eye-space angle at the primary measured from
// the drawn depths.
//
// Closed form. In the cut camera's perspective-divided space (u = x / s, v = y / s, s = depth),
// the box's footprint [lo, hi] (widened by one pixel) and back depth `back` (far corner + margin),
// a wall from edge e leans out from e's view ray by a = aperture / 2 in eye space at the primary:
// its tangent there has direction angle psi = atan(e) +/- a from the view axis (+ on the left and
// bottom, - on the right and top: away from the box), so
// d(u s)/ds = tan(psi) at s = back, and the wall (a plane in (u, v, s)) is u(s) = e -/+ k (back - s)
// with k = |tan(psi) - e| / back. The frustum's depth is the minimum over its planes:
//     s(u, v) = back - max(0, (lo_u - u) / k_left, (u - hi_u) / k_right, (lo_v - v) / k_bottom, (v - hi_v) / k_top)
// drawn where s >= the rim (the model's nearest depth), 0 (nothing cut) elsewhere.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "cone_field/cone_image.h"
#include "cutaway/renderer_readback.h"
#include "gl_test_support.h"
#include "grid/box_grid.h"
#include "grid/cell_geometry.h"

namespace cutaway::test {
namespace {

constexpr int width = 320, height = 240;
constexpr int primary_i = 1, primary_j = 4, primary_k = 2;  // off the image centre, far from the camera

const grid::CornerPointGrid& box_model() {
    static const grid::CornerPointGrid model = [] {
        grid::CornerPointGrid g = grid::make_box_grid({{6, 6, 3}, {100, 100, 20}, {0, 0, 1000}, 0, 0.0});
        g.set_property("PORO", std::vector<float>(std::size_t(6 * 6 * 3), 0.2f));
        return g;
    }();
    return model;
}

/// The frustum of the one primary in the cut camera's perspective-divided space.
struct Frustum {
    glm::dvec2 lo{1e30}, hi{-1e30};  ///< widened footprint, u and v
    double back = 0;                 ///< back face depth
    double rim = 0;                  ///< walls stop here
    std::array<double, 4> k{};       ///< u or v per depth unit: left, right, bottom, top

    /// The closed-form cut depth at (u, v); 0 where nothing is cut.
    double depth(glm::dvec2 uv) const {
        const double reach = std::max({0.0, (lo.x - uv.x) / k[0], (uv.x - hi.x) / k[1], (lo.y - uv.y) / k[2], (uv.y - hi.y) / k[3]});
        const double s = back - reach;
        return s >= rim ? s : 0.0;
    }
};

Frustum expected_frustum(const pipeline::CutawayRenderer& renderer, const pipeline::Camera& camera,
                         const pipeline::FrameSettings& settings) {
    const pipeline::ModelFrame& frame = renderer.frame();
    Frustum f;
    double far_corner = 0;
    const grid::CellCorners corners = grid::cell_corners(box_model(), primary_i, primary_j, primary_k);
    for (const grid::Point3& corner : corners) {
        const glm::dvec4 eye = glm::dmat4(camera.view) * glm::dvec4(glm::dvec3(frame.to_render(corner)), 1.0);
        const double s = -eye.z;
        f.lo = glm::min(f.lo, glm::dvec2(eye) / s);
        f.hi = glm::max(f.hi, glm::dvec2(eye) / s);
        far_corner = std::max(far_corner, s);
    }
    const double pixel_uv = 1.0 / camera.focal_px();
    f.lo -= pixel_uv;
    f.hi += pixel_uv;
    f.back = std::min(far_corner + double(settings.back_margin * frame.radius()), double(camera.far_plane));
    double nearest = camera.far_plane;  // the model's nearest depth: its bounding box's nearest corner
    for (int c = 0; c < 8; ++c) {
        const glm::vec4 corner{c & 1 ? frame.render_max.x : frame.render_min.x, c & 2 ? frame.render_max.y : frame.render_min.y,
                               c & 4 ? frame.render_max.z : frame.render_min.z, 1.0f};
        nearest = std::min(nearest, double(-(camera.view * corner).z));
    }
    f.rim = std::min(std::max(nearest, double(camera.near_plane)), f.back);
    const glm::dvec2 half(glm::radians(double(settings.aperture_h_deg) / 2), glm::radians(double(settings.aperture_v_deg) / 2));
    const auto k = [&](double edge, double side, double angle) {  // side -1: left/bottom, +1: right/top
        const double psi = std::atan(edge) - side * angle;
        return std::abs(psi) >= std::numbers::pi / 2 - 1e-5 ? 1e4 / f.back : std::abs(std::tan(psi) - edge) / f.back;
    };
    f.k = {k(f.lo.x, -1, half.x), k(f.hi.x, 1, half.x), k(f.lo.y, -1, half.y), k(f.hi.y, 1, half.y)};
    return f;
}

/// (u, v) of the centre of pixel (x, y), rows top to bottom as read_strategy_cut returns them.
glm::dvec2 pixel_uv(const pipeline::Camera& camera, int x, int y) {
    const glm::dvec2 ndc((x + 0.5) / camera.width * 2.0 - 1.0, (camera.height - 1 - y + 0.5) / camera.height * 2.0 - 1.0);
    return ndc / glm::dvec2(camera.projection[0][0], camera.projection[1][1]);
}

/// The wall's angle from the view ray through the back face's edge, measured on the drawn cut at
/// three wall pixels 1, 2, 3 pixels outside the footprint along the row or column through its
/// centre. On a plane of (u, v, s) the eye-space x = u s is quadratic in s, so the secant through
/// two points is the tangent at their mid depth and the tangent is linear in s: two secants give
/// the tangent at the back face exactly (up to depth rounding). `axis` 0: u (left/right), 1: v.
double measured_wall_angle(const cone_field::FloatImage& cut, const pipeline::Camera& camera, const Frustum& f,
                           int axis, int side) {
    const glm::dvec2 centre = (f.lo + f.hi) * 0.5;
    const double edge = side < 0 ? f.lo[axis] : f.hi[axis];
    // The pixel whose centre is nearest the edge, along the axis through the centre.
    const auto pixel_of = [&](glm::dvec2 uv) {
        const glm::dvec2 ndc = uv * glm::dvec2(camera.projection[0][0], camera.projection[1][1]);
        return glm::ivec2(int(std::floor((ndc.x + 1) / 2 * camera.width)), camera.height - 1 - int(std::floor((ndc.y + 1) / 2 * camera.height)));
    };
    glm::dvec2 at_edge = centre;
    at_edge[axis] = edge;
    glm::ivec2 step(0);
    step[axis] = axis == 0 ? side : -side;  // rows run top to bottom
    const glm::ivec2 first = pixel_of(at_edge) + step;
    const auto eye = [&](glm::ivec2 p) {
        const double s = cut.at(p.x, p.y);
        EXPECT_GT(s, 0.0) << "not on the wall";
        return glm::dvec2(pixel_uv(camera, p.x, p.y)[axis] * s, s);
    };
    const glm::dvec2 a = eye(first), b = eye(first + step), c = eye(first + 2 * step);
    const double near_secant = (a.x - b.x) / (a.y - b.y), far_secant = (b.x - c.x) / (b.y - c.y);
    const double near_mid = (a.y + b.y) / 2, far_mid = (b.y + c.y) / 2;
    const double tangent = near_secant + (near_secant - far_secant) / (near_mid - far_mid) * (f.back - near_mid);
    const double direction = std::atan(tangent);  // dx/ds at the back face: from the axis
    return side < 0 ? direction - std::atan(edge) : std::atan(edge) - direction;
}

struct ApertureCase {
    float horizontal_deg, vertical_deg;
};

class FrustumWalls : public ::testing::TestWithParam<ApertureCase> {};

TEST_P(FrustumWalls, DrawnCutDepthEqualsTheClosedFormWallWithinAPixel) {
    auto renderer = make_renderer(box_model(), width, height);
    std::vector<std::uint8_t> flags(std::size_t(6 * 6 * 3), 0);
    flags[std::size_t(primary_i + 6 * (primary_j + 6 * primary_k))] = 1;
    renderer->select(flags);
    const pipeline::Camera camera = pipeline::make_orbit_camera(renderer->frame(), {0, 35, 0, glm::vec3(0)}, width, height);
    pipeline::FrameSettings settings;
    settings.strategy = "frustum";
    settings.aperture_h_deg = GetParam().horizontal_deg;
    settings.aperture_v_deg = GetParam().vertical_deg;
    settings.mean_filter = 0;
    settings.ssao = false;
    settings.colour_bar = false;
    renderer->render(settings, camera);
    const cone_field::FloatImage cut = pipeline::RendererProbe(*renderer).read_strategy_cut(camera);
    const Frustum f = expected_frustum(*renderer, camera, settings);
    ASSERT_GT(f.back - f.rim, 0.1 * f.back) << "walls too short to test";

    // "Within a pixel": where the wall's depth changes by delta over one pixel, the rasteriser
    // may give a pixel the depth of its neighbour (coverage rules at the footprint's edges, the
    // rim); elsewhere the difference is float rounding of a depth stored in [0, 1] of
    // (far - near), a few 1e-7 of it, bounded here by 1e-5 of the depth range.
    const double rounding = 1e-5 * (camera.far_plane - camera.near_plane);
    int compared = 0, on_walls = 0;
    for (int y = 1; y + 1 < height; ++y)
        for (int x = 1; x + 1 < width; ++x) {
            const double expected = f.depth(pixel_uv(camera, x, y));
            double delta = 0;
            for (const glm::ivec2 n : {glm::ivec2(x - 1, y), glm::ivec2(x + 1, y), glm::ivec2(x, y - 1), glm::ivec2(x, y + 1)})
                delta = std::max(delta, std::abs(f.depth(pixel_uv(camera, n.x, n.y)) - expected));
            const double drawn = cut.at(x, y);
            ++compared;
            if (expected > 0 && expected < f.back - 1e-9) ++on_walls;
            ASSERT_NEAR(drawn, expected, delta + rounding) << "pixel " << x << ", " << y;
        }
    EXPECT_GT(on_walls, 1000) << "the walls cover too few pixels for the test to mean anything";
    RecordProperty("wall_pixels", on_walls);

    // The angle at the primary, from the drawn depths. Stored depths are rounded to about 1e-7 of
    // the depth range, 1e-4 of the depth step between pixels here; extrapolating two secants to
    // the back face magnifies that a few times: far below the 0.05 degree allowed.
    if (GetParam().horizontal_deg < 180 && GetParam().vertical_deg < 180) {
        EXPECT_NEAR(measured_wall_angle(cut, camera, f, 0, -1), glm::radians(settings.aperture_h_deg / 2), glm::radians(0.05));
        EXPECT_NEAR(measured_wall_angle(cut, camera, f, 0, 1), glm::radians(settings.aperture_h_deg / 2), glm::radians(0.05));
        EXPECT_NEAR(measured_wall_angle(cut, camera, f, 1, -1), glm::radians(settings.aperture_v_deg / 2), glm::radians(0.05));
        EXPECT_NEAR(measured_wall_angle(cut, camera, f, 1, 1), glm::radians(settings.aperture_v_deg / 2), glm::radians(0.05));
    }
}

// Narrow, the default (60), wide and unequal, and 180 (flat walls: the back depth everywhere
// inside the rim's footprint, which covers the whole image).
INSTANTIATE_TEST_SUITE_P(Apertures, FrustumWalls,
                         ::testing::Values(ApertureCase{30, 30}, ApertureCase{60, 60}, ApertureCase{120, 50}, ApertureCase{180, 180}));

}  // namespace
}  // namespace cutaway::test

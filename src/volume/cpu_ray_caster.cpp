#include "volume/cpu_ray_caster.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <thread>
#include <vector>

#include "volume/annotations.h"
#include "volume/ray_march.h"
#include "volume/view_geometry.h"

namespace cutaway::volume {

namespace {

std::uint8_t to_byte(float v) { return std::uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }

struct RowCounts {
    std::uint64_t samples = 0;
    std::uint64_t rays = 0;
};

/// Renders GL row `y` (0 = bottom) into image row height - 1 - y.
RowCounts render_row(const VolumeScene& scene, const RayCastSettings& settings, const ViewGeometry& view, int y,
                     gl::RgbaImage& image) {
    RowCounts counts;
    const Rgba bg = settings.background;
    for (int x = 0; x < settings.width; ++x) {
        const VoxelRay ray = pixel_ray(view, x, y, settings.width, settings.height);
        RayResult result;
        float t_enter = 0, t_exit = 0;
        if (intersect_box(ray.origin, ray.direction, view.box, t_enter, t_exit)) {
            result = march_ray(scene, settings, ray.origin + ray.direction * t_enter, ray.origin + ray.direction * t_exit,
                               jitter_fraction(std::uint32_t(x), std::uint32_t(y)));
            ++counts.rays;
            counts.samples += result.samples;
        }
        std::uint8_t* pixel = image.at(x, settings.height - 1 - y);
        const float behind = 1.0f - result.alpha;
        pixel[0] = to_byte(result.colour.r + behind * bg.r);
        pixel[1] = to_byte(result.colour.g + behind * bg.g);
        pixel[2] = to_byte(result.colour.b + behind * bg.b);
        pixel[3] = 255;
    }
    return counts;
}

}  // namespace

CastResult cast_rays_cpu(const VolumeScene& scene, const RayCastSettings& settings, unsigned threads) {
    validate(settings);
    const ViewGeometry view = make_view(scene.volume->dims, settings);
    CastResult result;
    result.image.width = settings.width;
    result.image.height = settings.height;
    result.image.pixels.assign(std::size_t(settings.width) * std::size_t(settings.height) * 4, 0);

    const unsigned workers = threads > 0 ? threads : std::max(1u, std::thread::hardware_concurrency());
    std::atomic<int> next_row{0};
    std::vector<RowCounts> totals(workers);
    {
        std::vector<std::jthread> pool;
        for (unsigned w = 0; w < workers; ++w)
            pool.emplace_back([&, w] {
                for (int y = next_row++; y < settings.height; y = next_row++) {
                    const RowCounts row = render_row(scene, settings, view, y, result.image);
                    totals[w].samples += row.samples;
                    totals[w].rays += row.rays;
                }
            });
    }
    for (const RowCounts& t : totals) {
        result.samples += t.samples;
        result.rays += t.rays;
    }
    if (settings.colour_bar) draw_annotations(result.image, scene, view, settings);
    return result;
}

}  // namespace cutaway::volume

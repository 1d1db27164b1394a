#include "volume/ray_march.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cutaway::volume {

namespace {

std::uint32_t pcg_hash(std::uint32_t v) {
    const std::uint32_t state = v * 747796405u + 2891336453u;
    const std::uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

/// Distance along `dir` from p (inside block `block`) to that block's far boundary.
float block_exit_distance(glm::vec3 p, glm::vec3 dir, glm::ivec3 block, float block_size) {
    float exit = std::numeric_limits<float>::max();
    for (int axis = 0; axis < 3; ++axis) {
        if (dir[axis] == 0) continue;
        const float bound = (float(block[axis]) + (dir[axis] > 0 ? 1.0f : 0.0f)) * block_size;
        exit = std::min(exit, (bound - p[axis]) / dir[axis]);
    }
    return exit;
}

}  // namespace

float jitter_fraction(std::uint32_t x, std::uint32_t y) {
    return float(pcg_hash(x + pcg_hash(y)) >> 8u) * (1.0f / 16777216.0f);
}

float sample_level(const QuantisedVolume& volume, glm::vec3 p) {
    const CubeDims& d = volume.dims;
    const glm::ivec3 size(d.samples, d.crosslines, d.inlines);
    const glm::vec3 u = p - 0.5f;
    const glm::vec3 base = glm::floor(u);
    const glm::vec3 f = u - base;
    glm::ivec3 lo, hi;
    for (int axis = 0; axis < 3; ++axis) {
        lo[axis] = std::clamp(int(base[axis]), 0, size[axis] - 1);
        hi[axis] = std::clamp(int(base[axis]) + 1, 0, size[axis] - 1);
    }
    auto level = [&](int t, int x, int i) {
        return float(volume.levels[(std::size_t(i) * std::size_t(d.crosslines) + std::size_t(x)) * std::size_t(d.samples) +
                                   std::size_t(t)]);
    };
    auto lerp = [](float a, float b, float w) { return a + w * (b - a); };
    const float c00 = lerp(level(lo.x, lo.y, lo.z), level(hi.x, lo.y, lo.z), f.x);
    const float c10 = lerp(level(lo.x, hi.y, lo.z), level(hi.x, hi.y, lo.z), f.x);
    const float c01 = lerp(level(lo.x, lo.y, hi.z), level(hi.x, lo.y, hi.z), f.x);
    const float c11 = lerp(level(lo.x, hi.y, hi.z), level(hi.x, hi.y, hi.z), f.x);
    return lerp(lerp(c00, c10, f.y), lerp(c01, c11, f.y), f.z);
}

bool intersect_box(glm::vec3 origin, glm::vec3 direction, glm::vec3 box, float& t_enter, float& t_exit) {
    const glm::vec3 inverse = 1.0f / direction;
    const glm::vec3 t0 = (glm::vec3(0) - origin) * inverse;
    const glm::vec3 t1 = (box - origin) * inverse;
    const glm::vec3 near = glm::min(t0, t1), far = glm::max(t0, t1);
    t_enter = std::max(std::max(near.x, near.y), std::max(near.z, 0.0f));
    t_exit = std::min(std::min(far.x, far.y), far.z);
    return t_exit > t_enter;
}

RayResult march_ray(const VolumeScene& scene, const RayCastSettings& settings, glm::vec3 entry, glm::vec3 exit,
                    float start_fraction) {
    RayResult ray;
    const glm::vec3 span = exit - entry;
    const float length = glm::length(span);
    if (!(length > 0)) return ray;
    const glm::vec3 dir = span / length;
    const float step = settings.step;
    const float start = settings.jitter ? start_fraction * step : 0.0f;
    const BlockGrid& blocks = scene.blocks;
    const glm::ivec3 block_max(blocks.blocks.samples - 1, blocks.blocks.crosslines - 1, blocks.blocks.inlines - 1);
    const float block_size = float(blocks.block_size);

    for (int i = 0;;) {
        const float t = start + float(i) * step;
        if (t >= length) break;
        const glm::vec3 p = entry + dir * t;
        if (settings.empty_space_skipping) {
            const glm::ivec3 block = glm::clamp(glm::ivec3(glm::floor(p / block_size)), glm::ivec3(0), block_max);
            const std::size_t index = (std::size_t(block.z) * std::size_t(blocks.blocks.crosslines) + std::size_t(block.y)) *
                                          std::size_t(blocks.blocks.samples) + std::size_t(block.x);
            if (!scene.occupied[index]) {
                i += std::max(1, int(std::ceil(block_exit_distance(p, dir, block, block_size) / step)));
                continue;
            }
        }
        const Rgba c = lookup(scene.table, sample_level(*scene.volume, p));
        const float a = settings.opacity_correction ? 1.0f - std::pow(1.0f - c.a, step) : c.a;
        const float weight = (1.0f - ray.alpha) * a;
        ray.colour += weight * glm::vec3(c.r, c.g, c.b);
        ray.alpha += weight;
        ++ray.samples;
        ++i;
        if (settings.early_termination && ray.alpha >= settings.early_termination_alpha) break;
    }
    return ray;
}

}  // namespace cutaway::volume

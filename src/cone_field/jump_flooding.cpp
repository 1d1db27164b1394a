#include "cone_field/jump_flooding.h"

#include <bit>
#include <stdexcept>
#include <string>

#include "cone_field/cone_slope.h"

namespace cutaway::cone_field {
namespace {

constexpr int no_owner = -1;

/// Per pixel, the index into the seed list of the seed it holds, or no_owner.
using OwnerImage = std::vector<int>;

/// The seed list index of each seed pixel, no_owner elsewhere.
OwnerImage initial_owners(const SeedImage& seeds, const std::vector<Seed>& seed_list) {
    OwnerImage owners(seeds.depth.pixels.size(), no_owner);
    for (std::size_t i = 0; i < seed_list.size(); ++i) {
        owners[seeds.depth.index(seed_list[i].x, seed_list[i].y)] = int(i);
    }
    return owners;
}

double height_at(const Seed& seed, double slope, int x, int y) {
    return cone_height(seed.depth, slope, seed.x - x, seed.y - y);
}

/// One jump flooding pass with step `step`: reads `previous`, writes `next`.
void flood_pass(const std::vector<Seed>& seed_list, double slope, int width, int height, int step,
                const OwnerImage& previous, OwnerImage& next) {
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const std::size_t here = std::size_t(y) * std::size_t(width) + std::size_t(x);
            int best_owner = previous[here];
            double best_height =
                best_owner == no_owner ? 0.0 : height_at(seed_list[std::size_t(best_owner)], slope, x, y);
            for (int ty = -1; ty <= 1; ++ty) {
                for (int tx = -1; tx <= 1; ++tx) {
                    const int nx = x + tx * step;
                    const int ny = y + ty * step;
                    if (nx < 0 || nx >= width || ny < 0 || ny >= height) continue;
                    const int owner = previous[std::size_t(ny) * std::size_t(width) + std::size_t(nx)];
                    if (owner == no_owner || owner == best_owner) continue;
                    const double candidate = height_at(seed_list[std::size_t(owner)], slope, x, y);
                    if (best_owner == no_owner || candidate > best_height) {
                        best_owner = owner;
                        best_height = candidate;
                    }
                }
            }
            next[here] = best_owner;
        }
    }
}

}  // namespace

std::string_view jfa_variant_name(JfaVariant variant) {
    switch (variant) {
    case JfaVariant::jfa: return "JFA";
    case JfaVariant::jfa_plus_1: return "JFA+1";
    case JfaVariant::jfa_plus_2: return "JFA+2";
    case JfaVariant::one_plus_jfa: return "1+JFA";
    case JfaVariant::jfa_squared: return "JFA^2";
    }
    throw std::invalid_argument("unknown jump flooding variant");
}

std::vector<int> jfa_steps(JfaVariant variant, int width, int height) {
    check_image_size(width, height, "jump flooding");
    // Halving from half the power of two covering the image reaches every pixel in log2 passes.
    std::vector<int> plain;
    for (int step = std::max(1, int(std::bit_ceil(unsigned(std::max(width, height)))) / 2); step >= 1; step /= 2) {
        plain.push_back(step);
    }
    std::vector<int> steps = plain;
    switch (variant) {
    case JfaVariant::jfa: return steps;
    case JfaVariant::jfa_plus_1: steps.push_back(1); return steps;
    case JfaVariant::jfa_plus_2: steps.insert(steps.end(), {2, 1}); return steps;
    case JfaVariant::one_plus_jfa: steps.insert(steps.begin(), 1); return steps;
    case JfaVariant::jfa_squared: steps.insert(steps.end(), plain.begin(), plain.end()); return steps;
    }
    throw std::invalid_argument("unknown jump flooding variant");
}

FloatImage jump_flooding_cut(const SeedImage& seeds, double slope_per_pixel, JfaVariant variant) {
    const std::vector<int> steps = jfa_steps(variant, seeds.width(), seeds.height());
    return jump_flooding_cut(seeds, slope_per_pixel, steps);
}

FloatImage jump_flooding_cut(const SeedImage& seeds, double slope_per_pixel, std::span<const int> steps) {
    check_slope_per_pixel(slope_per_pixel);
    for (const int step : steps) {
        if (step < 1) {
            throw std::invalid_argument("jump flooding: steps must be >= 1 pixel, got " + std::to_string(step));
        }
    }
    const std::vector<Seed> seed_list = collect_seeds(seeds);
    const int width = seeds.width();
    const int height = seeds.height();
    OwnerImage owners = initial_owners(seeds, seed_list);
    OwnerImage scratch(owners.size());
    for (const int step : steps) {
        flood_pass(seed_list, slope_per_pixel, width, height, step, owners, scratch);
        owners.swap(scratch);
    }
    FloatImage cut(width, height);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const int owner = owners[cut.index(x, y)];
            if (owner == no_owner) continue;
            cut.at(x, y) = float(std::max(0.0, height_at(seed_list[std::size_t(owner)], slope_per_pixel, x, y)));
        }
    }
    return cut;
}

}  // namespace cutaway::cone_field

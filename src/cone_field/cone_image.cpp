#include "cone_field/cone_image.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace cutaway::cone_field {

void check_image_size(int width, int height, const char* what) {
    const std::string size = std::to_string(width) + " x " + std::to_string(height);
    if (width < 1 || height < 1) {
        throw std::invalid_argument(std::string(what) + ": size must be positive, got " + size);
    }
    if (width > max_image_side || height > max_image_side ||
        std::size_t(width) * std::size_t(height) > max_image_pixels) {
        throw std::invalid_argument(std::string(what) + ": size " + size + " is beyond the limit of " +
                                    std::to_string(max_image_side) + " pixels a side and " +
                                    std::to_string(max_image_pixels) + " pixels");
    }
}

FloatImage::FloatImage(int width_px, int height_px, float fill) : width(width_px), height(height_px) {
    check_image_size(width, height, "image");
    pixels.assign(std::size_t(width) * std::size_t(height), fill);
}

void check_image(const FloatImage& image, const char* what) {
    check_image_size(image.width, image.height, what);
    if (image.pixels.size() != std::size_t(image.width) * std::size_t(image.height)) {
        throw std::invalid_argument(std::string(what) + ": holds " + std::to_string(image.pixels.size()) +
                                    " pixels, its size says " + std::to_string(image.width) + " x " +
                                    std::to_string(image.height));
    }
}

void check_seed_image(const SeedImage& seeds) {
    check_image(seeds.depth, "seed image");
    for (const float depth : seeds.depth.pixels) {
        if (std::isnan(depth) || depth == std::numeric_limits<float>::infinity()) {
            throw std::invalid_argument("seed image: a seed depth must be finite (or no_seed), got " +
                                        std::to_string(depth));
        }
    }
}

std::vector<Seed> collect_seeds(const SeedImage& seeds) {
    check_seed_image(seeds);
    std::vector<Seed> list;
    for (int y = 0; y < seeds.height(); ++y) {
        for (int x = 0; x < seeds.width(); ++x) {
            if (seeds.has_seed(x, y)) list.push_back({x, y, seeds.depth.at(x, y)});
        }
    }
    return list;
}

}  // namespace cutaway::cone_field

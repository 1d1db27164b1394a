#include "cutaway/cell_id_image.h"

#include <stdexcept>

namespace cutaway::pipeline {

gl::RgbaImage encode_cell_ids(const std::vector<std::uint32_t>& ids, int width, int height) {
    if (ids.size() != std::size_t(width) * std::size_t(height))
        throw std::invalid_argument("cell ids: " + std::to_string(ids.size()) + " values for a " + std::to_string(width) +
                                    "x" + std::to_string(height) + " image");
    gl::RgbaImage image{width, height, std::vector<std::uint8_t>(ids.size() * 4)};
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const std::uint32_t id = ids[std::size_t(height - 1 - y) * std::size_t(width) + std::size_t(x)];
            std::uint8_t* p = image.at(x, y);
            for (int byte = 0; byte < 4; ++byte) p[byte] = std::uint8_t(id >> (8 * byte));
        }
    return image;
}

std::vector<std::uint32_t> decode_cell_ids(const gl::RgbaImage& image) {
    std::vector<std::uint32_t> ids(std::size_t(image.width) * std::size_t(image.height));
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const std::uint8_t* p = image.at(x, y);
            ids[std::size_t(image.height - 1 - y) * std::size_t(image.width) + std::size_t(x)] =
                std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24;
        }
    return ids;
}

}  // namespace cutaway::pipeline

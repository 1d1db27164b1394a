#include "cutaway/cut_surface/cut_depth_image.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace cutaway::pipeline {
namespace {

void check_size(const gl::Texture& depth, const Camera& camera, int width, int height) {
    if (depth.width() != camera.width || depth.height() != camera.height || width != camera.width ||
        height != camera.height)
        throw std::invalid_argument("cut depth image " + std::to_string(width) + "x" + std::to_string(height) +
                                    ", texture " + std::to_string(depth.width()) + "x" +
                                    std::to_string(depth.height()) + ": expected the cut camera's " +
                                    std::to_string(camera.width) + "x" + std::to_string(camera.height));
}

}  // namespace

cone_field::FloatImage read_cut_depth_texture(const gl::Texture& depth, const Camera& camera) {
    check_size(depth, camera, camera.width, camera.height);
    cone_field::FloatImage image(camera.width, camera.height);
    std::vector<float> stored(image.pixel_count());
    glGetTextureImage(depth.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, GLsizei(stored.size() * sizeof(float)),
                      stored.data());
    const float span = camera.far_plane - camera.near_plane;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const float value = stored[image.index(x, image.height - 1 - y)];
            image.at(x, y) = value > 0.0f ? camera.near_plane + value * span : 0.0f;
        }
    return image;
}

void write_cut_depth_texture(const cone_field::FloatImage& cut, const Camera& camera, const gl::Texture& depth) {
    check_size(depth, camera, cut.width, cut.height);
    std::vector<float> stored(cut.pixel_count());
    const float span = camera.far_plane - camera.near_plane;
    for (int y = 0; y < cut.height; ++y)
        for (int x = 0; x < cut.width; ++x) {
            const float s = cut.at(x, y);
            stored[cut.index(x, cut.height - 1 - y)] =
                s > camera.near_plane ? std::min((s - camera.near_plane) / span, 1.0f) : 0.0f;
        }
    glTextureSubImage2D(depth.id(), 0, 0, 0, cut.width, cut.height, GL_DEPTH_COMPONENT, GL_FLOAT, stored.data());
}

float storable_cut_depth(float depth, const Camera& camera) {
    return depth > camera.near_plane ? std::min(depth, camera.far_plane) : 0.0f;
}

}  // namespace cutaway::pipeline

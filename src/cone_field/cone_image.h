#pragma once
// The images the cone-field cut strategies read and write: a float image (the cut surface) and a
// seed image (the rear hull of the primaries). Plain CPU memory, no OpenGL.
#include <cstddef>
#include <limits>
#include <vector>

namespace cutaway::cone_field {

/// Largest accepted width or height, pixels. Far beyond any framebuffer; guards against garbage.
inline constexpr int max_image_side = 32768;
/// Largest accepted pixel count (2^28: 1 GiB of floats).
inline constexpr std::size_t max_image_pixels = std::size_t(1) << 28;

/// Throws std::invalid_argument unless 1 <= width, height <= max_image_side and
/// width * height <= max_image_pixels. `what` names the image in the message.
void check_image_size(int width, int height, const char* what);

/// A width x height image of floats, row-major, row 0 at the top of the screen: pixel (x, y) at
/// index y * width + x. For a cut surface: linear eye-space depth per pixel (distance from the
/// camera, larger = farther, the seeds' units), 0 where nothing is cut.
struct FloatImage {
    int width = 0;
    int height = 0;
    std::vector<float> pixels;  ///< width * height values

    FloatImage() = default;
    /// Throws std::invalid_argument for sizes check_image_size refuses.
    FloatImage(int width, int height, float fill = 0.0f);

    std::size_t index(int x, int y) const { return std::size_t(y) * std::size_t(width) + std::size_t(x); }
    float at(int x, int y) const { return pixels[index(x, y)]; }
    float& at(int x, int y) { return pixels[index(x, y)]; }
    std::size_t pixel_count() const { return pixels.size(); }
};

/// Throws std::invalid_argument if the size is refused or pixels.size() != width * height.
void check_image(const FloatImage& image, const char* what);

/// Depth value of a pixel that holds no seed. Any finite depth is a seed; NaN and +infinity are
/// refused by the strategies.
inline constexpr float no_seed = -std::numeric_limits<float>::infinity();

/// Seeds of the cone field: per pixel the linear eye-space depth z(q) of the primaries' rear hull
/// (distance from the camera, larger = farther), or no_seed where no primary covers the pixel.
/// Same layout as FloatImage.
struct SeedImage {
    FloatImage depth;

    SeedImage() = default;
    /// An image with no seed at all.
    SeedImage(int width, int height) : depth(width, height, no_seed) {}

    int width() const { return depth.width; }
    int height() const { return depth.height; }
    bool has_seed(int x, int y) const { return depth.at(x, y) != no_seed; }
    void set_seed(int x, int y, float seed_depth) { depth.at(x, y) = seed_depth; }
};

/// One seed pixel: position in pixels (x right, y down) and its depth.
struct Seed {
    int x = 0;
    int y = 0;
    float depth = 0.0f;
};

/// Throws std::invalid_argument if the image is malformed or a depth is NaN or +infinity.
void check_seed_image(const SeedImage& seeds);

/// The seed pixels in row-major order, after check_seed_image.
std::vector<Seed> collect_seeds(const SeedImage& seeds);

}  // namespace cutaway::cone_field

#pragma once
// 8-bit RGBA images read back from GL and written as PNG (stb_image_write).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace cutaway::gl {

/// Rows top to bottom, 4 bytes per pixel.
struct RgbaImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> pixels;
    const std::uint8_t* at(int x, int y) const { return &pixels[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4]; }
    std::uint8_t* at(int x, int y) { return &pixels[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4]; }
};

/// Reads colour attachment `attachment` of framebuffer `framebuffer` (0: default), flipping GL's
/// bottom-up rows.
RgbaImage read_rgba(unsigned framebuffer, unsigned attachment, int width, int height);

/// The PNG file's bytes; throws io::OutputError naming `path` (where they are going) if the image
/// cannot be encoded.
std::string encode_png(const RgbaImage& image, const std::filesystem::path& path);

/// Written under a temporary name and renamed (io::write_file); throws io::OutputError naming the
/// path and the reason if it cannot be written, leaving no partial file.
void write_png(const RgbaImage& image, const std::filesystem::path& path);

/// Reads a PNG as RGBA (for golden-image tests); throws GlError naming the path.
RgbaImage read_png(const std::filesystem::path& path);

}  // namespace cutaway::gl

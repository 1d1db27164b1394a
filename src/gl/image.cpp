#include "gl/image.h"

#include <epoxy/gl.h>
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <cstring>
#include <string>

#include "gl/gl_error.h"
#include "io/output_error.h"
#include "io/output_batch.h"
#include "io/path_text.h"

namespace cutaway::gl {

RgbaImage read_rgba(unsigned framebuffer, unsigned attachment, int width, int height) {
    RgbaImage image{width, height, std::vector<std::uint8_t>(std::size_t(width) * std::size_t(height) * 4)};
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    glReadBuffer(framebuffer == 0 ? GL_BACK : GL_COLOR_ATTACHMENT0 + attachment);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, image.pixels.data());
    const std::size_t row = std::size_t(width) * 4;
    std::vector<std::uint8_t> swap(row);
    for (int y = 0; y < height / 2; ++y) {
        std::uint8_t* top = image.pixels.data() + std::size_t(y) * row;
        std::uint8_t* bottom = image.pixels.data() + std::size_t(height - 1 - y) * row;
        std::memcpy(swap.data(), top, row);
        std::memcpy(top, bottom, row);
        std::memcpy(bottom, swap.data(), row);
    }
    return image;
}

std::string encode_png(const RgbaImage& image, const std::filesystem::path& path) {
    // Encoded in memory first: stb's file writer ignores failed writes (a full disk gave an empty
    // file and success).
    std::string png;
    const auto append = [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data), std::size_t(size));
    };
    if (!stbi_write_png_to_func(append, &png, image.width, image.height, 4, image.pixels.data(), image.width * 4))
        throw io::OutputError(io::shown_path(path) + ": cannot encode a " + std::to_string(image.width) + "x" +
                              std::to_string(image.height) + " PNG");
    return png;
}

void write_png(const RgbaImage& image, const std::filesystem::path& path) { io::write_file(path, encode_png(image, path)); }

RgbaImage read_png(const std::filesystem::path& path) {
    int width = 0, height = 0, channels = 0;
    stbi_uc* data = stbi_load(path.string().c_str(), &width, &height, &channels, 4);
    if (data == nullptr) throw GlError("image " + path.string() + ": cannot be read as PNG");
    RgbaImage image{width, height, std::vector<std::uint8_t>(data, data + std::size_t(width) * std::size_t(height) * 4)};
    stbi_image_free(data);
    return image;
}

}  // namespace cutaway::gl

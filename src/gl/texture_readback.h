#pragma once
// A whole texture read back to the CPU (level 0), `components` values of T per texel in the
// layout glGetTextureImage gives for `format` and `type`: rows bottom to top.
#include <cstddef>
#include <vector>

#include "gl/gl_objects.h"

namespace cutaway::gl {

/// Into `out`, resized (a vector read every frame keeps its storage).
template <typename T>
void read_texels_into(const Texture& texture, GLenum format, GLenum type, std::size_t components, std::vector<T>& out) {
    out.resize(std::size_t(texture.width()) * std::size_t(texture.height()) * components);
    glGetTextureImage(texture.id(), 0, format, type, GLsizei(out.size() * sizeof(T)), out.data());
}

template <typename T>
std::vector<T> read_texels(const Texture& texture, GLenum format, GLenum type, std::size_t components) {
    std::vector<T> values;
    read_texels_into(texture, format, type, components, values);
    return values;
}

}  // namespace cutaway::gl

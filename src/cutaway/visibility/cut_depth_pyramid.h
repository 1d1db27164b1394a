#pragma once
// Min/max pyramid of the cut depth image (hierarchical-Z culling, SPEC.md section 6), in one
// buffer of (min, max) float pairs, level after level, rows bottom to top. Level 0 is half the
// cut image; texel t of a level covers texels 2t and 2t+1 of the level below along each axis,
// and the last texel of a level also covers the odd leftover, so cut texel x lies in texel
// min(x >> (level + 1), level width - 1) of every level.
#include <glm/glm.hpp>
#include <vector>

#include "common/shared_constants.h"
#include "gl/gl_objects.h"
#include "gl/shader_library.h"

namespace cutaway::pipeline {

/// Storage binding of the pyramid buffer (visibility/cut_pyramid.comp writes it).
inline constexpr unsigned cut_pyramid_binding = shared::ssbo_cut_pyramid;
/// Texture unit of the pyramid as an RG32F buffer texture (visibility/classify.glsl reads it).
inline constexpr unsigned cut_pyramid_texture_unit = 17;
/// Enough levels for a 65536-pixel side.
inline constexpr int max_pyramid_levels = 16;

class CutDepthPyramid {
public:
    explicit CutDepthPyramid(const gl::ShaderLibrary& shaders);
    /// Rebuilds every level from `cut_surface` (R32F cut depth, 0 = nothing cut).
    void build(const gl::Texture& cut_surface);
    /// Binds the pyramid's buffer texture and sets `program`'s pyramid_texels, pyramid_levels,
    /// pyramid_sizes and pyramid_offsets.
    void bind_for(const gl::Program& program) const;
    int levels() const { return int(sizes_.size()); }
    glm::ivec2 level_size(int level) const { return sizes_[std::size_t(level)]; }
    /// (min, max) per texel of `level`, rows bottom to top (tests).
    std::vector<glm::vec2> read_level(int level) const;
    std::size_t memory_bytes() const { return buffer_.size_bytes(); }

private:
    gl::Program first_, next_;
    gl::Buffer buffer_;
    gl::BufferTexture texels_;  ///< buffer_ as RG32F texels
    int width_ = 0, height_ = 0;
    std::vector<glm::ivec2> sizes_;
    std::vector<int> offsets_;
};

}  // namespace cutaway::pipeline

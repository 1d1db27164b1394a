#include "cutaway/visibility/cut_depth_pyramid.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "gl/compute_dispatch.h"
#include "gl/uniforms.h"

namespace cutaway::pipeline {
namespace {
constexpr int group_x = 64, group_y = 4;  // visibility/cut_pyramid.comp local size
}  // namespace

CutDepthPyramid::CutDepthPyramid(const gl::ShaderLibrary& shaders)
    : first_(shaders.build({{GL_COMPUTE_SHADER, "visibility/cut_pyramid.comp"}}, {{"FIRST_LEVEL", ""}})),
      next_(shaders.build({{GL_COMPUTE_SHADER, "visibility/cut_pyramid.comp"}})) {}

void CutDepthPyramid::build(const gl::Texture& cut_surface) {
    const int width = std::max(1, cut_surface.width() / 2), height = std::max(1, cut_surface.height() / 2);
    if (width != width_ || height != height_) {
        sizes_.clear();
        offsets_.clear();
        std::size_t texels = 0;
        for (glm::ivec2 size(width, height);; size = glm::max(size / 2, glm::ivec2(1))) {
            sizes_.push_back(size);
            offsets_.push_back(int(texels));
            texels += std::size_t(size.x) * std::size_t(size.y);
            if (size == glm::ivec2(1)) break;
        }
        if (levels() > max_pyramid_levels)
            throw std::invalid_argument("cut image " + std::to_string(cut_surface.width()) + "x" +
                                        std::to_string(cut_surface.height()) + ": the culling pyramid holds at most " +
                                        std::to_string(max_pyramid_levels) + " levels");
        GLint max_texels = 0;
        glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &max_texels);
        if (texels > std::size_t(max_texels))
            throw std::invalid_argument("cut image " + std::to_string(cut_surface.width()) + "x" +
                                        std::to_string(cut_surface.height()) + ": its culling pyramid needs " +
                                        std::to_string(texels) + " texels, more than this GL's buffer textures hold (" +
                                        std::to_string(max_texels) + ")");
        texels_ = {};
        buffer_ = gl::Buffer(texels * sizeof(glm::vec2), nullptr);
        texels_ = gl::BufferTexture(buffer_, GL_RG32F);
        width_ = width;
        height_ = height;
    }
    buffer_.bind_base(GL_SHADER_STORAGE_BUFFER, cut_pyramid_binding);
    for (int level = 0; level < levels(); ++level) {
        const gl::Program& p = level == 0 ? first_ : next_;
        if (level == 0) {
            glBindImageTexture(0, cut_surface.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32F);
            gl::wait_for_draws_before_image_loads();  // the surface may come from a draw or an image store
        } else {
            gl::set_uniform(p, "below_size", sizes_[std::size_t(level - 1)]);
            gl::set_uniform(p, "below_offset", offsets_[std::size_t(level - 1)]);
        }
        gl::set_uniform(p, "level_size", sizes_[std::size_t(level)]);
        gl::set_uniform(p, "level_offset", offsets_[std::size_t(level)]);
        p.use();
        const glm::ivec2 size = sizes_[std::size_t(level)];
        glDispatchCompute(gl::group_count(size.x, group_x), gl::group_count(size.y, group_y), 1);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);  // the next level, then the culling
    }
}

void CutDepthPyramid::bind_for(const gl::Program& program) const {
    gl::set_uniform(program, "pyramid_levels", levels());
    if (levels() > 0) {
        glProgramUniform2iv(program.id(), program.uniform("pyramid_sizes"), levels(), &sizes_[0].x);
        glProgramUniform1iv(program.id(), program.uniform("pyramid_offsets"), levels(), offsets_.data());
        gl::set_uniform(program, "pyramid_texels", int(cut_pyramid_texture_unit));
        texels_.bind(cut_pyramid_texture_unit);
    }
}

std::vector<glm::vec2> CutDepthPyramid::read_level(int level) const {
    const glm::ivec2 size = level_size(level);
    std::vector<glm::vec2> texels(std::size_t(size.x) * std::size_t(size.y));
    glGetNamedBufferSubData(buffer_.id(), GLintptr(std::size_t(offsets_[std::size_t(level)]) * sizeof(glm::vec2)),
                            GLsizeiptr(texels.size() * sizeof(glm::vec2)), texels.data());
    return texels;
}

}  // namespace cutaway::pipeline

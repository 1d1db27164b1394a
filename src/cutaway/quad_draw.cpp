#include "cutaway/quad_draw.h"

#include <algorithm>
#include <array>
#include <optional>
#include <span>
#include <vector>

#include "gl/fence.h"

namespace cutaway::pipeline {
namespace {

std::vector<std::uint16_t> quad_indices() {
    constexpr std::array<std::uint16_t, 6> triangles{0, 1, 2, 0, 2, 3};
    std::vector<std::uint16_t> indices;
    indices.reserve(6 * QuadDraw::quads_per_chunk);
    for (std::uint32_t q = 0; q < QuadDraw::quads_per_chunk; ++q)
        for (std::uint16_t corner : triangles) indices.push_back(std::uint16_t(4 * q + corner));
    return indices;
}

/// Calls draw_group(first chunk, chunk count) for each group of chunks_per_group chunks, waiting
/// before each for the group before the last one (QuadDraw::chunks_per_group).
template <typename DrawGroup>
void draw_throttled(std::size_t chunks, DrawGroup&& draw_group) {
    std::optional<gl::Fence> last, before_last;
    for (std::size_t first = 0; first < chunks; first += QuadDraw::chunks_per_group) {
        if (before_last) before_last->wait();
        draw_group(first, std::min(QuadDraw::chunks_per_group, chunks - first));
        before_last = std::move(last);
        last.emplace();
    }
}

}  // namespace

QuadDraw::QuadDraw() : indices_(gl::Buffer::from(std::span<const std::uint16_t>(quad_indices()))) {
    glVertexArrayElementBuffer(vertex_array_.id(), indices_.id());
}

void QuadDraw::draw(std::size_t faces) const {
    if (faces == 0) return;
    const std::size_t chunks = chunks_for(faces);
    std::vector<GLsizei> counts(chunks, GLsizei(6 * quads_per_chunk));
    counts.back() = GLsizei(6 * (faces - (chunks - 1) * quads_per_chunk));
    std::vector<const void*> offsets(chunks, nullptr);
    std::vector<GLint> base_vertices(chunks);
    for (std::size_t c = 0; c < chunks; ++c) base_vertices[c] = GLint(4 * c * quads_per_chunk);
    vertex_array_.bind();
    draw_throttled(chunks, [&](std::size_t first, std::size_t count) {
        glMultiDrawElementsBaseVertex(GL_TRIANGLES, counts.data() + first, GL_UNSIGNED_SHORT, offsets.data() + first,
                                      GLsizei(count), base_vertices.data() + first);
    });
}

void QuadDraw::draw_indirect(const gl::Buffer& commands, std::size_t chunks) const {
    if (chunks == 0) return;
    vertex_array_.bind();
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, commands.id());
    draw_throttled(chunks, [](std::size_t first, std::size_t count) {
        // The commands are tightly packed DrawElementsIndirectCommands (5 uints each).
        glMultiDrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_SHORT,
                                    reinterpret_cast<const void*>(first * 5 * sizeof(GLuint)), GLsizei(count), 0);
    });
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
}

}  // namespace cutaway::pipeline

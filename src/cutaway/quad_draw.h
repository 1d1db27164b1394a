#pragma once
// Faces drawn as indexed quads: 4 vertices per face (common/face.vert: gl_VertexID / 4 = face,
// gl_VertexID % 4 = corner) and two triangles (0, 1, 2), (0, 2, 3) from one shared 16-bit index
// pattern, drawn in chunks of quads_per_chunk faces with a base vertex. The vertex stage (serial
// on llvmpipe) then runs 4 times per face instead of 6, and no index buffer grows with the model.
#include <cstddef>
#include <cstdint>

#include "gl/gl_objects.h"

namespace cutaway::pipeline {

class QuadDraw {
public:
    /// Faces per chunk: 4 x 16384 vertices = the 65536 a 16-bit index reaches.
    static constexpr std::uint32_t quads_per_chunk = 16384;
    /// Chunks drawn between two fences. Before a group is issued, the group before the last one
    /// must have completed, so at most two groups (32K faces) are queued at a time. llvmpipe
    /// bins a whole draw into scenes before its threads rasterise them; unthrottled, stage 2's
    /// 1.1M faces at scale-10m queued scenes that raised the peak resident memory per active
    /// cell markedly (alternating direct runs, same image, the frame no slower).
    /// Each halving of the group was measured the same way at scale-10m, 1080p: 4 -> 2 chunks
    /// and 2 -> 1 chunk each lowered the resident memory, the warm frames (stage 2 and the
    /// primaries too) within this machine's noise, perhaps slightly slower at 1 chunk; the same
    /// image.
    /// A GPU always has the last group queued while the CPU waits for the one before it.
    static constexpr std::size_t chunks_per_group = 1;
    /// Chunks (draw commands) that `faces` faces need.
    static std::size_t chunks_for(std::size_t faces) { return (faces + quads_per_chunk - 1) / quads_per_chunk; }

    QuadDraw();

    /// Draws faces [0, faces) of the face range bound at the face binding with the bound program.
    void draw(std::size_t faces) const;
    /// Draws with `chunks` DrawElementsIndirectCommands from `commands` (chunk c: base vertex
    /// 4 c quads_per_chunk, a count of 6 per face; visibility/finish_culling.comp writes them).
    void draw_indirect(const gl::Buffer& commands, std::size_t chunks) const;

private:
    gl::Buffer indices_;
    gl::VertexArray vertex_array_;  ///< holds the index buffer; no attributes
};

}  // namespace cutaway::pipeline

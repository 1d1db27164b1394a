#pragma once
// Output-sensitive stage 2 (SPEC.md section 6): every frame a compute pass picks, on the GPU, the
// secondary faces that can reach a pixel, and the draw reads their count from an indirect
// command. Built once per model: the cells grouped in IJK bricks with their boxes.
#include <cstdint>
#include <vector>

#include "cutaway/camera.h"
#include "cutaway/camera_blocks.h"
#include "cutaway/frame_targets.h"
#include "cutaway/grid_buffers.h"
#include "cutaway/visibility/cell_bricks.h"
#include "cutaway/visibility/cut_depth_pyramid.h"
#include "gl/program_cache.h"
#include "gl/shader_library.h"

namespace cutaway::pipeline {

/// What the last selection did (read back on request, never to draw).
struct CullingCounts {
    std::uint64_t faces = 0;             ///< faces in the draw
    std::uint64_t faces_requested = 0;   ///< faces selected (> faces only if the buffer overflowed)
    std::uint64_t bricks = 0;
    std::uint64_t bricks_culled = 0;     ///< outside the frustum or entirely in front of the cut
    std::uint64_t cells_culled = 0;      ///< cells of culled bricks, and culled secondaries of the others
                                         ///< (with keep_rear_faces, those in front of the cut still give their rear faces)
    std::uint64_t cells_behind = 0;      ///< secondaries entirely behind the cut (exposed faces only)
    std::uint64_t cells_straddling = 0;  ///< secondaries the cut passes through (every visible face)
};

class VisibleFaces {
public:
    /// `face_limit`: every face the selection can pick (the exposed faces plus one side of each
    /// interior face, selectable_face_capacity). The face buffer starts at `initial_capacity`
    /// records (at most `face_limit`) and grows, up to `face_limit`, when a frame selects more
    /// (grow_to_fit): a frame draws about a tenth of the faces a model has, and on llvmpipe every
    /// buffer byte is resident memory.
    VisibleFaces(const gl::ShaderLibrary& shaders, const CellBricks& bricks, std::size_t face_limit,
                 std::size_t initial_capacity);

    /// Builds the cut's min/max pyramid (from `cut`, the texture stage 2 reads; null: no cut) and
    /// selects the faces of secondary cells for the model `camera`. `keep_rear_faces` (freeze
    /// view, stage 2 keeping the model camera's rear shell): cells in front of the cut still give
    /// their exposed faces seen from inside.
    /// `cameras` binds `camera` and `cut_camera` (common/cameras.glsl) for the classification.
    void select(const GridBuffers& grid, const CameraBlocks& cameras, const Camera& camera, const CutTargets* cut,
                const Camera& cut_camera, bool keep_rear_faces = false);
    /// Draws the selected faces with the bound face program, as `grid`'s indexed quads.
    void draw(const GridBuffers& grid) const;
    /// Reads the counters of the last selection back (a GPU->CPU sync: not in timed frames).
    CullingCounts read_counts() const;
    /// After a finished frame, when the face buffer is smaller than the limit: reads the last
    /// selection's face count (4 bytes) and, if the buffer was too small for it, grows the buffer
    /// to fit it with a margin. True when it grew: that frame dropped faces and must be drawn
    /// again. A buffer sized to the limit reads nothing.
    bool grow_to_fit();
    /// Bytes grow_to_fit has read back so far.
    std::size_t count_readback_bytes() const { return count_readback_bytes_; }
    /// Sizes the face buffer to `faces` records (clamped to 1..face_limit); it grows from there.
    void set_capacity(std::size_t faces);
    /// Grows the face buffer to `face_limit` (no selection can overflow it then).
    void reserve_limit() { set_capacity(face_limit_); }
    std::size_t face_capacity() const { return face_capacity_; }
    /// Reads the last selection's face records back in drawing order (a GPU->CPU sync, for tests).
    std::vector<std::uint32_t> read_faces() const;
    std::size_t memory_bytes() const;
    const CutDepthPyramid& pyramid() const { return pyramid_; }

private:
    /// The selected faces' records in brick, cell and side order (visibility/scan_bricks.comp,
    /// visibility/write_visible_faces.comp): the draw order no longer depends on the order the
    /// culling's invocations ran in, so coincident faces tie the same way on any GPU.
    void write_in_brick_order(const GridBuffers& grid);

    gl::ProgramCache classify_, cull_;  ///< variant CUT_CAMERA_IS_VIEW (visibility/classify.glsl)
    gl::Program finish_, scan_bricks_, scan_blocks_, write_faces_;
    CutDepthPyramid pyramid_;
    gl::Buffer brick_cells_, brick_begin_, brick_boxes_;
    gl::Buffer brick_classes_;  ///< class of each brick this frame (classify_bricks.comp)
    gl::BufferTexture brick_cell_texels_, brick_begin_texels_, brick_class_texels_;  ///< cull_cells.comp's reads
    std::size_t brick_count_ = 0;
    std::size_t face_limit_ = 0;
    std::size_t face_capacity_ = 0;
    std::size_t count_readback_bytes_ = 0;
    gl::Buffer counters_, faces_;
    std::size_t chunks_ = 0;  ///< draw commands: QuadDraw chunks of the face capacity
    gl::Buffer commands_;     ///< DrawElementsIndirectCommand per chunk (finish_culling.comp)
    gl::Buffer cell_masks_;      ///< sides each cell gives this frame, a byte per brick_cells slot
    gl::Buffer brick_counts_;    ///< faces each brick gives this frame
    gl::Buffer brick_offsets_;   ///< each brick's first record within its scan block
    gl::Buffer block_offsets_;   ///< each scan block's first record
};

}  // namespace cutaway::pipeline

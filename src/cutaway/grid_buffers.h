#pragma once
// GPU copies of a GridLayout and of the face lists of one primary selection (std430 buffers,
// bound at the binding points declared in shaders/common/grid.glsl and face.vert).
#include <glm/glm.hpp>

#include "common/shared_constants.h"
#include "cutaway/grid_layout.h"
#include "cutaway/quantised_values.h"
#include "cutaway/quad_draw.h"
#include "gl/gl_objects.h"
#include "grid/zcorn_store.h"

namespace cutaway::pipeline {

/// Binding points shared with the shaders.
enum BufferBinding : unsigned { faces_binding = shared::ssbo_faces, primary_cells_binding = shared::ssbo_primary_cells,
                                cell_face_classes_binding = shared::ssbo_cell_face_classes,
                                primary_bits_binding = shared::ssbo_primary_bits };
/// Texture units of the geometry's buffer textures (common/grid.glsl).
enum GeometryTextureUnit : unsigned {
    pillar_texture_unit = shared::tex_pillars, corner_depth_texture_unit = shared::tex_corner_depths,
    cell_texture_unit = shared::tex_cells, value_texture_unit = shared::tex_cell_values,
    face_class_texture_unit = shared::tex_face_classes, primary_bit_texture_unit = shared::tex_primary_bits };

struct FaceBuffer {
    gl::Buffer buffer;
    std::size_t count = 0;
    static FaceBuffer from(const std::vector<std::uint32_t>& records);
};

/// A per-model face list for the depth-only passes that let the rasteriser cull triangles
/// (common/face_corner.vert), split by how a face's corners (face_corners order) turn seen from
/// outside its cell: counter-clockwise, or clockwise for the cells whose corner order gives
/// inward normals in render space (GridLayout::cells bit 31). Each part is drawn with its own
/// glFrontFace, so every vertex keeps the corner order common/face.vert gives it, and with it
/// the same rasterised depths.
struct WoundFaces {
    FaceBuffer counter_clockwise, clockwise;
    std::size_t count() const { return counter_clockwise.count + clockwise.count; }
    static WoundFaces from(const std::vector<std::uint32_t>& records, const GridLayout& layout);
};

class GridBuffers {
public:
    /// Keeps a reference to `layout`, which must outlive it; reads the corner depths from `zcorn`.
    /// Throws std::invalid_argument when the geometry exceeds the GL buffer-texture limit.
    GridBuffers(const GridLayout& layout, const grid::ZcornStore& zcorn, const ModelFrame& frame);

    /// One value per active cell (compact order), at full precision.
    void set_values(const std::vector<float>& compact_values);
    /// One value per active cell at 16 bits (quantised_values.h): half the upload, for colouring
    /// only. The shaders decode it (the value_decoding uniform set_geometry_uniforms sets).
    void set_values(const QuantisedValues& compact_values);
    /// Whether the values set last are 16-bit codes (a range selection over them is not exact).
    bool values_quantised() const { return values_quantised_; }
    /// One primary bit per compact cell (bit c % 32 of word c / 32), read by the culling pass
    /// and by the selection passes (selection/gpu_primary_selection.h) that build the lists.
    void upload_primary_bits(const std::vector<std::uint32_t>& bits);
    std::vector<std::uint32_t> read_primary_bits() const;
    /// Sizes the primary cell and face lists for the selection passes to fill (grows only).
    void resize_primary_lists(std::size_t cells, std::size_t faces);

    /// Every face of every secondary cell of the selection (the all-faces path's stage 2).
    void set_secondary_faces(const std::vector<std::uint32_t>& records) { secondary_ = FaceBuffer::from(records); }
    /// Binds the buffer textures of pillars, corner depths, cells and values.
    void bind_geometry() const;
    /// Sets the uniforms common/grid.glsl reads (grid_size, up_sign, z_scale, value_decoding) on `program`.
    void set_geometry_uniforms(const gl::Program& program) const;
    /// Binds the per-cell face classes and primary bits (visibility/cull_cells.comp).
    void bind_culling_inputs() const;
    /// Draws `faces` as indexed quads (quad_draw.h) with the bound face program.
    void draw_faces(const FaceBuffer& faces) const;
    /// Draws `faces` with the rasteriser culling the triangles that face `culled` (GL_FRONT or
    /// GL_BACK: towards or away from the eye, seen from outside their cell).
    void draw_faces(const WoundFaces& faces, GLenum culled) const;
    const QuadDraw& quads() const { return quads_; }

    glm::uvec2 grid_size() const { return grid_size_; }
    /// Corner-plane slots per layer: 1 for a compact ZCORN (shared layer interfaces), 2 for a full
    /// one. A cell record's top-face texel is ((slots k NY + j) NX + i).
    unsigned plane_slots_per_layer() const { return plane_slots_per_layer_; }
    const ModelFrame& frame() const { return frame_; }
    const FaceBuffer& secondary_faces() const { return secondary_; }
    const FaceBuffer& primary_faces() const { return primary_; }
    const FaceBuffer& primary_cells() const { return primary_cells_; }
    /// The uncut model's outer surface (grid_layout.h outer_faces): the shell, the fault faces
    /// no active cell across covers, less the walls of enclosed pockets. The rear shell keeps its
    /// farthest depth, the shell contours its nearest.
    const WoundFaces& outer_faces() const { return outer_; }
    /// Every face of every active cell (built on first use: only the all-faces path needs it).
    const FaceBuffer& all_faces() const;
    /// Bytes of every buffer allocated so far.
    std::size_t memory_bytes() const;

private:
    const GridLayout& layout_;
    glm::uvec2 grid_size_;
    unsigned plane_slots_per_layer_;
    ModelFrame frame_;
    gl::Buffer pillars_, corner_planes_, cells_, values_, cell_face_classes_, primary_bits_;
    FaceBuffer secondary_, primary_, primary_cells_;
    WoundFaces outer_;
    /// The geometry read through the texture path (common/grid.glsl): llvmpipe gathers texels
    /// with vector loads, while each storage-buffer load at a varying index is a per-lane loop.
    gl::BufferTexture pillar_texels_, corner_plane_texels_, cell_texels_, value_texels_;
    gl::BufferTexture value16_texels_;  ///< values_'s first 2 bytes per cell as 16-bit codes
    /// value = x + y x texel: (0, 1) for float values, (offset, span) for 16-bit codes.
    glm::vec2 value_decoding_{0, 1};
    bool values_quantised_ = false;
    gl::BufferTexture face_class_texels_, primary_bit_texels_;  ///< the culling pass's reads (texel gathers)
    mutable FaceBuffer all_;
    QuadDraw quads_;
};

}  // namespace cutaway::pipeline

#pragma once
// The grid as the GPU reads it, built on the CPU without expanding to triangles: pillars, one
// 32-bit record per active cell and one per face; the corner depths go to the GPU straight from
// the grid's ZCORN store (grid_buffers.h). The vertex shader rebuilds corner positions from
// pillars and depths (shaders/common/grid.glsl).
#include <cstdint>
#include <vector>

#include "cutaway/model_frame.h"
#include "grid/face_classification.h"
#include "grid/zcorn_store.h"

namespace cutaway::pipeline {

/// Face record: bits 0-26 compact (active) cell index, 27-29 FaceSide, 30-31 FaceClass
/// (shaders/common/grid.glsl decodes it).
inline constexpr std::uint32_t face_cell_bits = 27;
inline constexpr std::size_t max_render_cells = std::size_t(1) << face_cell_bits;

inline std::uint32_t pack_face(std::uint32_t compact_cell, grid::FaceSide side, grid::FaceClass face_class) {
    return compact_cell | (std::uint32_t(side) << face_cell_bits) | (std::uint32_t(face_class) << (face_cell_bits + 3));
}

/// The compact cell of a face record.
inline std::uint32_t face_record_cell(std::uint32_t record) { return record & ((std::uint32_t(1) << face_cell_bits) - 1); }

struct GridLayout {
    /// 2 x vec4 per pillar (top xyz, 0; bottom xyz, 0), centred model units (not flipped).
    /// The renderer frees them once GridBuffers has uploaded them.
    std::vector<float> pillars;
    /// Per active cell: Eclipse cell index (bits 0-30) and bit 31 set when the face corner order
    /// of shaders/common/grid.glsl gives inward normals in render space for this cell.
    std::vector<std::uint32_t> cells;
    /// Classification of the six faces of every active cell by compact index, 2 bits per side
    /// (FaceClass at bits 2 s, sides in FaceSide order), as the GPU reads them.
    std::vector<std::uint16_t> face_classes;
    /// The classification's tolerance (grid::FaceClassification::tolerance): corner depths this
    /// close are one corner.
    double face_tolerance = 0;

    /// Bit 31 of `cells`: the face corner order gives inward normals for this cell.
    bool inward_corner_order(std::size_t compact) const { return (cells[compact] & 0x80000000u) != 0; }

    grid::FaceClass face_class(std::size_t compact, grid::FaceSide side) const {
        return grid::FaceClass((face_classes[compact] >> (2 * unsigned(side))) & 3u);
    }
};

/// Throws std::invalid_argument if the model has more than max_render_cells active cells.
GridLayout build_grid_layout(const grid::CornerPointGrid& grid, const grid::FaceClassification& classes,
                             const ModelFrame& frame);

/// Face records for one primary selection.
struct FaceLists {
    std::vector<std::uint32_t> secondary;  ///< all six faces of every secondary cell
    std::vector<std::uint32_t> primary;    ///< faces of primary cells not shared with another primary
    std::vector<std::uint32_t> primary_cells;  ///< compact indices of the primary cells
};

/// `primary_flags`: one per Eclipse cell (grid::select_primaries). `with_secondary`: also list
/// every face of every secondary cell (only the all-faces path draws that list).
FaceLists build_face_lists(const grid::CornerPointGrid& grid, const GridLayout& layout,
                           const std::vector<std::uint8_t>& primary_flags, bool with_secondary);

/// Faces the visible path can select at most: exposed faces once per cell, interior faces once
/// per pair (plus a margin for ties, where both copies of an edge-on face count as seen from inside).
std::size_t selectable_face_capacity(const GridLayout& layout);

/// One flag per Eclipse cell: active (a cell of `layout`).
std::vector<bool> active_cells(const GridLayout& layout, const grid::GridDims& dims);

/// The uncut model's outer surface: shell faces and the fault faces some part of which no active
/// cell across covers (grid/fault_cover.h), less the walls of enclosed pockets of inactive cells
/// (`enclosed`, grid/enclosed_pockets.h). The farthest of them along a ray is where the ray leaves
/// the model (rear_shell_depth.h), the nearest where it enters (the shell contours). A covered
/// fault face is neither, and 33% of sapphire's shell and fault faces, 45% of petra's, are covered
/// ones; nor is a pocket's wall, which no ray from outside reaches before crossing an active cell.
/// (With the shell faces alone the contours looked through the steps that faults make in the
/// model's top into the cells behind, and drew stray lines there.)
std::vector<std::uint32_t> outer_faces(const GridLayout& layout, const grid::ZcornStore& zcorn,
                                       const std::vector<bool>& active, const std::vector<bool>& enclosed);

/// Every face that is not interior (shell, fault, next to an inactive cell): what a frame
/// without a cut can show (exposed_surface.h).
std::vector<std::uint32_t> exposed_faces(const GridLayout& layout);

/// Every face of every active cell (the baseline frame).
std::vector<std::uint32_t> all_faces(const GridLayout& layout);

}  // namespace cutaway::pipeline

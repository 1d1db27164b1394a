#include "cutaway/grid_layout.h"

#include <limits>
#include <stdexcept>

#include "grid/cell_geometry.h"
#include "grid/fault_cover.h"

namespace cutaway::pipeline {
namespace {

constexpr std::uint32_t no_cell = std::numeric_limits<std::uint32_t>::max();

/// Eclipse index of the neighbour across `side`, or no_cell outside the grid.
std::uint32_t neighbour(const grid::GridDims& dims, std::size_t cell, grid::FaceSide side) {
    grid::CellIjk c = grid::cell_ijk(dims, cell);
    switch (side) {
        case grid::FaceSide::i_minus: --c.i; break;
        case grid::FaceSide::i_plus: ++c.i; break;
        case grid::FaceSide::j_minus: --c.j; break;
        case grid::FaceSide::j_plus: ++c.j; break;
        case grid::FaceSide::k_minus: --c.k; break;
        case grid::FaceSide::k_plus: ++c.k; break;
    }
    return dims.contains(c.i, c.j, c.k) ? std::uint32_t(dims.cell_index(c.i, c.j, c.k)) : no_cell;
}

}  // namespace

GridLayout build_grid_layout(const grid::CornerPointGrid& grid, const grid::FaceClassification& classes,
                             const ModelFrame& frame) {
    if (grid.active_count() > max_render_cells)
        throw std::invalid_argument("model has " + std::to_string(grid.active_count()) +
                                    " active cells; the renderer's face records hold at most " +
                                    std::to_string(max_render_cells));
    const grid::GridDims& dims = grid.dims();
    GridLayout layout;
    layout.pillars.reserve(8 * dims.pillar_count());
    for (int pj = 0; pj <= dims.ny; ++pj)
        for (int pi = 0; pi <= dims.nx; ++pi) {
            const grid::Pillar p = grid.pillar(pi, pj);
            for (const grid::Point3& end : {p.top, p.bottom}) {
                layout.pillars.push_back(float(end.x - frame.centre.x));
                layout.pillars.push_back(float(end.y - frame.centre.y));
                layout.pillars.push_back(float(end.z - frame.centre.z));
                layout.pillars.push_back(0.0f);
            }
        }
    // The shader's corner orders give outward normals for cells with positive signed volume in
    // model (x, y, z) space; render space flips z when up_sign < 0 (determinant sign up_sign).
    const bool render_flips = frame.up_sign < 0;
    // Compact index = rank among the active cells in Eclipse order (ActiveCellRank answers it
    // later from ACTNUM: this table lives only while the layout is built).
    std::vector<std::uint32_t> compact_of_cell(grid.cell_count(), no_cell);
    std::uint32_t active = 0;
    for (std::size_t cell = 0; cell < grid.cell_count(); ++cell)
        if (grid.active(cell)) compact_of_cell[cell] = active++;
    layout.cells.resize(active);
    layout.face_classes.resize(active);
    layout.face_tolerance = classes.tolerance();
    // Each active cell's records at its compact index (Eclipse order), the cells split over the threads.
    const std::ptrdiff_t cell_count = std::ptrdiff_t(grid.cell_count());
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t index = 0; index < cell_count; ++index) {
        const std::size_t cell = std::size_t(index);
        const std::uint32_t compact = compact_of_cell[cell];
        if (compact == no_cell) continue;
        const grid::CellIjk c = grid::cell_ijk(dims, cell);
        const bool negative = grid::signed_volume(grid::cell_corners(grid, c.i, c.j, c.k)) < 0;
        layout.cells[compact] = std::uint32_t(cell) | ((negative != render_flips) ? 0x80000000u : 0u);
        std::uint16_t packed = 0;
        for (int side = 0; side < 6; ++side)
            packed |= std::uint16_t(unsigned(classes.at(cell, grid::FaceSide(side))) << (2 * side));
        layout.face_classes[compact] = packed;
    }
    return layout;
}

FaceLists build_face_lists(const grid::CornerPointGrid& grid, const GridLayout& layout,
                           const std::vector<std::uint8_t>& primary_flags, bool with_secondary) {
    if (primary_flags.size() != grid.cell_count())
        throw std::invalid_argument("primary flags: " + std::to_string(primary_flags.size()) +
                                    " entries, expected one per cell");
    FaceLists lists;
    for (std::uint32_t compact = 0; compact < layout.cells.size(); ++compact) {
        const std::size_t cell = layout.cells[compact] & 0x7fffffffu;
        const bool primary = primary_flags[cell] != 0;
        if (primary) lists.primary_cells.push_back(compact);
        for (int s = 0; s < 6; ++s) {
            const auto side = grid::FaceSide(s);
            const grid::FaceClass face_class = layout.face_class(compact, side);
            const std::uint32_t record = pack_face(compact, side, face_class);
            if (!primary) {
                if (with_secondary) lists.secondary.push_back(record);
                continue;
            }
            // A face shared with another primary is hidden inside the primary cluster.
            const std::uint32_t other = neighbour(grid.dims(), cell, side);
            const bool shared = face_class == grid::FaceClass::interior && other != no_cell && primary_flags[other] != 0;
            if (!shared) lists.primary.push_back(record);
        }
    }
    return lists;
}

std::size_t selectable_face_capacity(const GridLayout& layout) {
    std::size_t exposed = 0, interior = 0;
    for (std::size_t compact = 0; compact < layout.face_classes.size(); ++compact)
        for (int s = 0; s < 6; ++s) {
            const grid::FaceClass c = layout.face_class(compact, grid::FaceSide(s));
            if (c == grid::FaceClass::interior) ++interior;
            else if (c != grid::FaceClass::none) ++exposed;
        }
    const std::size_t faces = exposed + (interior + 1) / 2;
    return faces + faces / 64 + 1024;
}

namespace {
template <typename Keep>
std::vector<std::uint32_t> faces_where(const GridLayout& layout, Keep keep) {
    std::vector<std::uint32_t> faces;
    for (std::uint32_t compact = 0; compact < layout.cells.size(); ++compact)
        for (int s = 0; s < 6; ++s) {
            const grid::FaceClass face_class = layout.face_class(compact, grid::FaceSide(s));
            if (keep(face_class)) faces.push_back(pack_face(compact, grid::FaceSide(s), face_class));
        }
    return faces;
}
}  // namespace

std::vector<bool> active_cells(const GridLayout& layout, const grid::GridDims& dims) {
    std::vector<bool> active(dims.cell_count(), false);
    for (const std::uint32_t cell : layout.cells) active[cell & 0x7fffffffu] = true;
    return active;
}

namespace {
/// Whether the face of the cell at `at` on `side` walls in an enclosed pocket (the cell across is in one).
bool walls_pocket(const grid::GridDims& d, const std::vector<bool>& enclosed, grid::CellIjk at, grid::FaceSide side) {
    const grid::CellIjk n = grid::across(at, side);
    return d.contains(n.i, n.j, n.k) && enclosed[d.cell_index(n.i, n.j, n.k)];
}
}  // namespace

std::vector<std::uint32_t> outer_faces(const GridLayout& layout, const grid::ZcornStore& zcorn,
                                       const std::vector<bool>& active, const std::vector<bool>& enclosed) {
    const grid::GridDims& d = zcorn.dims();
    std::vector<std::uint32_t> faces;
    for (std::uint32_t compact = 0; compact < layout.cells.size(); ++compact) {
        const grid::CellIjk at = grid::cell_ijk(d, layout.cells[compact] & 0x7fffffffu);
        for (int s = 0; s < 6; ++s) {
            const grid::FaceSide side(static_cast<grid::FaceSide>(s));
            const grid::FaceClass face_class = layout.face_class(compact, side);
            const bool outer = (face_class == grid::FaceClass::shell && !walls_pocket(d, enclosed, at, side)) ||
                               (face_class == grid::FaceClass::fault && !grid::face_covered_across(zcorn, active, at.i, at.j, at.k, side));
            if (outer) faces.push_back(pack_face(compact, side, face_class));
        }
    }
    return faces;
}

std::vector<std::uint32_t> exposed_faces(const GridLayout& layout) {
    return faces_where(layout, [](grid::FaceClass c) { return c != grid::FaceClass::interior; });
}

std::vector<std::uint32_t> all_faces(const GridLayout& layout) {
    return faces_where(layout, [](grid::FaceClass) { return true; });
}

}  // namespace cutaway::pipeline

// Frustum union over clusters of primaries (the thesis's future work): adjacent primaries merged
// into IJK boxes (primary_clusters.h), one frustum per box, drawn as the frustum union draws one
// per cell (cell_boxes.h), so the fill cost falls with the number of boxes instead of primaries.
// A box's frustum starts from the (u, v, s) bounding box of all its cells' corners: its back face
// lies behind and around every cell of the box, so every primary pixel stays exposed, as with one
// frustum per cell. The walls differ from the per-cell union's (one wall per box side instead of
// a staircase of per-cell walls), so the context removed differs. Boxes are rebuilt on the CPU
// only when the selection changes (PrimarySelection::generation); per frame nothing is read back.
#include <cstdint>
#include <optional>
#include <vector>

#include "cutaway/cut_surface/cell_boxes.h"
#include "cutaway/cut_surface/frustum_union.h"
#include "cutaway/cut_surface/primary_clusters.h"

namespace cutaway::pipeline {
namespace {

/// The GPU copy of one selection's clusters.
struct ClusterBuffers {
    gl::Buffer range_buffer, cell_buffer;
    gl::BufferTexture ranges, cells;
    std::size_t count = 0;
};

ClusterBuffers upload_clusters(const PrimarySelection& selection) {
    std::vector<std::uint32_t> ranges, cells;  // (first, count) per cluster; compact cells
    const grid::GridDims& d = selection.dims;
    for (const IjkCellBox& b : primary_boxes(*selection.flags, d)) {
        const std::size_t first = cells.size();
        for (int k = b.k0; k <= b.k1; ++k)
            for (int j = b.j0; j <= b.j1; ++j)
                for (int i = b.i0; i <= b.i1; ++i)
                    cells.push_back((*selection.compact_of_cell)(d.cell_index(i, j, k)));
        ranges.push_back(std::uint32_t(first));
        ranges.push_back(std::uint32_t(cells.size() - first));
    }
    ClusterBuffers out;
    out.count = ranges.size() / 2;
    if (out.count == 0) return out;
    out.range_buffer = gl::Buffer::from(std::span<const std::uint32_t>(ranges));
    out.cell_buffer = gl::Buffer::from(std::span<const std::uint32_t>(cells));
    out.ranges = gl::BufferTexture(out.range_buffer, GL_RG32UI);
    out.cells = gl::BufferTexture(out.cell_buffer, GL_R32UI);
    return out;
}

class FrustumClusters final : public CutSurfaceStrategy {
public:
    explicit FrustumClusters(const gl::ShaderLibrary& shaders) : program_(build_cell_box_program(shaders, {.clusters = true})) {}

    void render(const CutSurfaceInputs& in, const CutTargets& targets) override {
        if (!in.selection.flags || !in.selection.compact_of_cell) return;
        if (generation_ != in.selection.generation) {
            clusters_ = upload_clusters(in.selection);
            generation_ = in.selection.generation;
        }
        if (clusters_.count == 0) return;
        const ClusterBoxes boxes{clusters_.ranges, clusters_.cells, clusters_.count};
        draw_cell_boxes(program_, in, targets.framebuffer, &boxes);
    }

private:
    gl::Program program_;
    ClusterBuffers clusters_;
    std::optional<std::uint64_t> generation_;
};

}  // namespace

CutSurfaceEntry frustum_clusters_entry() {
    return {"frustum-clusters", "gpu",
            "one frustum per IJK box of adjacent primaries, drawn like the frustum union; the boxes are built on the "
            "CPU once per selection, nothing per frame",
            [](const gl::ShaderLibrary& shaders) { return std::make_unique<FrustumClusters>(shaders); },
            {},
            true};
}

}  // namespace cutaway::pipeline

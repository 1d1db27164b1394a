#pragma once
// One rank's share of a distributed cutaway frame: its slab of the model (grid_block.h), drawn by
// an unmodified pipeline::CutawayRenderer whose frame hooks combine the cut after stage 1
// (cut_allreduce.h) and composite the G-buffer after stage 3 (scene_compositor.h). The
// screen-space passes run once, at rank 0, on the composited buffers. This header does not
// include MPI or IceT.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "cutaway/cutaway_renderer.h"
#include "distributed/cut_allreduce.h"
#include "distributed/grid_block.h"
#include "distributed/scene_compositor.h"

namespace cutaway::distributed {

/// Exchange costs of the last frame on this rank.
struct ExchangeCosts {
    double allreduce_ms = 0;         ///< the MPI_Allreduce of the cut alone
    double allreduce_wait_ms = 0;    ///< waiting for the slowest rank's stage 1 before it
    double composite_ms = 0;         ///< the IceT composites and the shell reduction alone
    double composite_wait_ms = 0;    ///< waiting for the slowest rank's stages 2 and 3 before them
    std::size_t allreduce_bytes = 0; ///< message size per rank
    std::size_t icet_bytes_sent = 0;
    std::size_t reduce_bytes_sent = 0;
};

class RankRenderer {
public:
    /// Collective (creates the IceT context). `whole`: the model, which every rank holds while this
    /// is built (only `slab`'s cells are kept); `frame`: the whole model's frame; `tolerance`: its
    /// face tolerance.
    RankRenderer(const gl::ShaderLibrary& shaders, const grid::CornerPointGrid& whole, const pipeline::ModelFrame& frame,
                 const grid::IjkBox& slab, double tolerance, int width, int height);
    /// Collective: the same for a block the rank cut from the grid it loaded (make_grid_block).
    RankRenderer(const gl::ShaderLibrary& shaders, GridBlock block, const pipeline::ModelFrame& frame, int width,
                 int height);

    pipeline::CutawayRenderer& renderer() { return renderer_; }
    const pipeline::CutawayRenderer& renderer() const { return renderer_; }
    const GridBlock& block() const { return block_; }

    /// Arrays of the block's source grid (one entry per cell of the whole model, or of the loaded
    /// block with its halo: GridBlock::source), narrowed to the slab.
    void set_colouring(const std::vector<float>& source_values, const pipeline::ColourBarLabel& label);
    void set_primaries(const std::vector<std::uint8_t>& source_flags);
    /// `box` in whole-model cell indices.
    void select_range(const grid::PrimaryRange& range, const std::optional<grid::IjkBox>& box = std::nullopt);

    /// Collective: one frame (CutawayRenderer::render with the hooks).
    pipeline::FrameTimes render(const pipeline::FrameSettings& settings, const pipeline::Camera& camera);
    const ExchangeCosts& last_exchange() const { return exchange_; }

    /// Rank 0, after a frame: the composited whole-model Eclipse id + 1 per pixel (rows bottom to
    /// top), and its final image and linear depth through renderer().
    const std::vector<std::uint32_t>& composited_ids() const { return compositor_.composited_ids(); }

private:
    GridBlock block_;
    pipeline::CutawayRenderer renderer_;
    CutAllreduce allreduce_;
    SceneCompositor compositor_;
    ExchangeCosts exchange_;
};

}  // namespace cutaway::distributed

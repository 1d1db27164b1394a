#include "distributed/rank_renderer.h"
#include "cutaway/renderer_readback.h"

#include <algorithm>
#include <utility>

namespace cutaway::distributed {

RankRenderer::RankRenderer(const gl::ShaderLibrary& shaders, const grid::CornerPointGrid& whole,
                           const pipeline::ModelFrame& frame, const grid::IjkBox& slab, double tolerance, int width,
                           int height)
    : RankRenderer(shaders, make_grid_block(whole, slab, tolerance), frame, width, height) {}

RankRenderer::RankRenderer(const gl::ShaderLibrary& shaders, GridBlock block, const pipeline::ModelFrame& frame,
                           int width, int height)
    : block_(std::move(block)),
      renderer_(shaders, block_.grid, frame, block_.classes, width, height),
      allreduce_(width, height),
      compositor_(width, height) {
    pipeline::FrameHooks hooks;
    hooks.combine_max = [this](const std::vector<const gl::Texture*>& images) { allreduce_.combine(images); };
    hooks.sum_centres = [this](const pipeline::CentreSum& own) {
        std::vector<double> values{own.sum.x, own.sum.y, own.sum.z, double(own.count)};
        allreduce_.sum(values);
        return pipeline::CentreSum{{values[0], values[1], values[2]}, std::uint64_t(values[3])};
    };
    hooks.combine_scene = [this](const pipeline::SceneTargets& scene) {
        std::vector<std::uint32_t> ids = pipeline::FrameReadback(renderer_).read_eclipse_ids();
        for (std::uint32_t& id : ids) id = block_.whole_id(id);
        compositor_.composite(scene, ids);
    };
    hooks.screen_passes = compositor_.displays();
    renderer_.set_hooks(std::move(hooks));
}

void RankRenderer::set_colouring(const std::vector<float>& source_values, const pipeline::ColourBarLabel& label) {
    renderer_.set_colouring(block_.own_values(source_values), label);
}

void RankRenderer::set_primaries(const std::vector<std::uint8_t>& source_flags) {
    renderer_.select(block_.own_values(source_flags));
}

void RankRenderer::select_range(const grid::PrimaryRange& range, const std::optional<grid::IjkBox>& box) {
    if (!box) {
        renderer_.select(range);
        return;
    }
    // The box in slab cell indices; empty (upper below lower) where it misses the slab.
    const grid::IjkBox& s = block_.box;
    renderer_.select({range, grid::IjkBox{std::max(box->i0, s.i0) - s.i0, std::max(box->j0, s.j0) - s.j0,
                                               std::max(box->k0, s.k0) - s.k0, std::min(box->i1, s.i1) - s.i0,
                                               std::min(box->j1, s.j1) - s.j0, std::min(box->k1, s.k1) - s.k0}});
}

pipeline::FrameTimes RankRenderer::render(const pipeline::FrameSettings& settings, const pipeline::Camera& camera) {
    allreduce_.start_frame();
    pipeline::FrameTimes times = renderer_.render(settings, camera);
    exchange_ = {allreduce_.last_mpi_ms(),          allreduce_.last_wait_ms(),         compositor_.last_exchange_ms(),
                 compositor_.last_wait_ms(),        allreduce_.message_bytes(),        compositor_.icet_bytes_sent(),
                 compositor_.reduce_bytes_sent()};
    return times;
}

}  // namespace cutaway::distributed

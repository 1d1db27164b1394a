// Frustum union (Carvalho et al.): runs on the GPU. Each primary cell is one point; the vertex
// shader builds its box in the cut camera's perspective-divided space, the geometry shader emits
// the back face and the four walls, and the depth test (cleared to 0, GL_GREATER) keeps the rear
// hull of the union (depth only). Cost: geometry is tiny, fill grows with primaries x wall area.
#include "cutaway/cut_surface/frustum_union.h"

#include "cutaway/cut_surface/cell_boxes.h"

namespace cutaway::pipeline {
namespace {

class FrustumUnion final : public CutSurfaceStrategy {
public:
    explicit FrustumUnion(const gl::ShaderLibrary& shaders) : program_(build_cell_box_program(shaders, {})) {}

    void render(const CutSurfaceInputs& in, const CutTargets& targets) override {
        draw_cell_boxes(program_, in, targets.framebuffer);
    }

private:
    gl::Program program_;
};

}  // namespace

CutSurfaceEntry frustum_union_entry() {
    return {"frustum", "gpu",
            "geometry is one point per primary; the cost is rasterising the frustum walls, which GPUs do in parallel",
            [](const gl::ShaderLibrary& shaders) { return std::make_unique<FrustumUnion>(shaders); }};
}

}  // namespace cutaway::pipeline

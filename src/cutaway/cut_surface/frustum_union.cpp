// Frustum union (Carvalho et al.): runs on the GPU. Each primary cell is one point; the vertex
// shader builds its box in the cut camera's perspective-divided space, the geometry shader emits
// the back face and the four walls, and the depth test (cleared to 0, GL_GREATER) keeps the rear
// hull of the union (depth only). Cost: geometry is tiny, fill grows with primaries x wall area.
#include "cutaway/cut_surface/frustum_union.h"

#include <cmath>

#include "gl/uniforms.h"

namespace cutaway::pipeline {
namespace {

class FrustumUnion final : public CutSurfaceStrategy {
public:
    explicit FrustumUnion(const gl::ShaderLibrary& shaders)
        : program_(shaders.build({{GL_VERTEX_SHADER, "cut_surface/frustum.vert"},
                                  {GL_GEOMETRY_SHADER, "cut_surface/frustum.geom"},
                                  {GL_FRAGMENT_SHADER, "cut_surface/frustum.frag"}})) {}

    void render(const CutSurfaceInputs& in, const CutTargets& targets) override {
        const FaceBuffer& cells = in.grid.primary_cells();
        if (cells.count == 0) return;
        const Camera& camera = in.cut_camera;
        const gl::Program& p = program_;
        gl::set_uniform(p, "grid_size", in.grid.grid_size());
        gl::set_uniform(p, "up_sign", float(in.grid.frame().up_sign));
        gl::set_uniform(p, "z_scale", float(in.grid.frame().z_scale));
        gl::set_uniform(p, "cut_view", camera.view);
        gl::set_uniform(p, "near_plane", camera.near_plane);
        gl::set_uniform(p, "far_plane", camera.far_plane);
        gl::set_uniform(p, "projection_scale", glm::vec2(camera.projection[0][0], camera.projection[1][1]));
        gl::set_uniform(p, "rim_depth", in.rim_depth);
        gl::set_uniform(p, "back_margin", in.back_margin);
        gl::set_uniform(p, "pixel_uv", 1.0f / camera.focal_px());
        // 90 degrees is a flat wall: a tangent of 1e4 puts the rim far outside any image.
        const auto tangent = [](float angle) { return std::min(std::tan(angle), 1e4f); };
        gl::set_uniform(p, "aperture_tangent", glm::vec2(tangent(in.aperture_h_rad), tangent(in.aperture_v_rad)));

        targets.framebuffer.bind();
        glViewport(0, 0, camera.width, camera.height);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_GREATER);
        glDepthMask(GL_TRUE);
        glDisable(GL_CULL_FACE);
        in.grid.bind_geometry();
        cells.buffer.bind_base(GL_SHADER_STORAGE_BUFFER, primary_cells_binding);
        p.use();
        glDrawArrays(GL_POINTS, 0, GLsizei(cells.count));
        glDepthFunc(GL_LESS);
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

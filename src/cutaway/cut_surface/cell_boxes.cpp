#include "cutaway/cut_surface/cell_boxes.h"

#include <algorithm>
#include <cmath>

#include "gl/uniforms.h"

namespace cutaway::pipeline {

gl::Program build_cell_box_program(const gl::ShaderLibrary& shaders, bool back_face_only) {
    gl::ShaderDefines defines;
    if (back_face_only) defines.emplace_back("BACK_FACE_ONLY", "");
    return shaders.build({{GL_VERTEX_SHADER, "cut_surface/frustum.vert"},
                          {GL_GEOMETRY_SHADER, "cut_surface/frustum.geom"},
                          {GL_FRAGMENT_SHADER, "cut_surface/frustum.frag"}},
                         defines);
}

void draw_cell_boxes(const gl::Program& p, const CutSurfaceInputs& in, const gl::Framebuffer& framebuffer) {
    const FaceBuffer& cells = in.grid.primary_cells();
    if (cells.count == 0) return;
    const Camera& camera = in.cut_camera;
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

    framebuffer.bind();
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

}  // namespace cutaway::pipeline

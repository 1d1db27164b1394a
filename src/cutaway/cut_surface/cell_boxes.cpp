#include "cutaway/cut_surface/cell_boxes.h"

#include "gl/uniforms.h"

namespace cutaway::pipeline {
namespace {
constexpr GLuint cluster_range_texture_unit = 12, cluster_cell_texture_unit = 13;  // frustum.vert (CLUSTERS)
}  // namespace

gl::Program build_cell_box_program(const gl::ShaderLibrary& shaders, const CellBoxProgramOptions& options) {
    gl::ShaderDefines defines;
    if (options.back_face_only) defines.emplace_back("BACK_FACE_ONLY", "");
    if (options.clusters) defines.emplace_back("CLUSTERS", "");
    if (options.constant_wall_slope) defines.emplace_back("CONSTANT_WALL_SLOPE", "");
    return shaders.build({{GL_VERTEX_SHADER, "cut_surface/frustum.vert"},
                          {GL_GEOMETRY_SHADER, "cut_surface/frustum.geom"},
                          {GL_FRAGMENT_SHADER, "cut_surface/frustum.frag"}},
                         defines);
}

void draw_cell_boxes(const gl::Program& p, const CutSurfaceInputs& in, const gl::Framebuffer& framebuffer,
                     const ClusterBoxes* clusters) {
    const FaceBuffer& cells = in.grid.primary_cells();
    const std::size_t boxes = clusters ? clusters->count : cells.count;
    if (boxes == 0) return;
    const Camera& camera = in.cut_camera;
    in.grid.set_geometry_uniforms(p);
    gl::set_uniform(p, "cut_view", camera.view);
    gl::set_uniform(p, "near_plane", camera.near_plane);
    gl::set_uniform(p, "far_plane", camera.far_plane);
    gl::set_uniform(p, "projection_scale", glm::vec2(camera.projection[0][0], camera.projection[1][1]));
    gl::set_uniform(p, "rim_depth", in.rim_depth);
    gl::set_uniform(p, "back_margin", in.back_margin);
    gl::set_uniform(p, "pixel_uv", 1.0f / camera.focal_px());
    gl::set_uniform(p, "wall_angle", glm::vec2(in.wall_angle_h_rad, in.wall_angle_v_rad));

    framebuffer.bind();
    glViewport(0, 0, camera.width, camera.height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);
    in.grid.bind_geometry();
    if (clusters) {
        clusters->ranges.bind(cluster_range_texture_unit);
        clusters->cells.bind(cluster_cell_texture_unit);
    } else {
        cells.buffer.bind_base(GL_SHADER_STORAGE_BUFFER, primary_cells_binding);
    }
    p.use();
    glDrawArrays(GL_POINTS, 0, GLsizei(boxes));
    glDepthFunc(GL_LESS);
}

}  // namespace cutaway::pipeline

#include "cutaway/cut_surface/cell_boxes.h"

#include "common/shared_constants.h"
#include "gl/uniforms.h"

namespace cutaway::pipeline {
namespace {
constexpr GLuint cluster_range_texture_unit = shared::tex_cluster_ranges, cluster_cell_texture_unit = shared::tex_cluster_cells;
constexpr GLuint opening_cells_binding = shared::ssbo_opening_cells;  // frustum.vert (OPENING)

/// The uniforms and depth state every box draw shares; the caller binds its cells and draws.
void prepare_boxes(const gl::Program& p, const CutSurfaceInputs& in, const gl::Framebuffer& framebuffer) {
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
}

void draw_points(const gl::Program& p, std::size_t points) {
    p.use();
    glDrawArrays(GL_POINTS, 0, GLsizei(points));
    glDepthFunc(GL_LESS);
}

}  // namespace

gl::Program build_cell_box_program(const gl::ShaderLibrary& shaders, const CellBoxProgramOptions& options) {
    gl::ShaderDefines defines;
    if (options.back_face_only) defines.emplace_back("BACK_FACE_ONLY", "");
    if (options.clusters) defines.emplace_back("CLUSTERS", "");
    if (options.constant_wall_slope) defines.emplace_back("CONSTANT_WALL_SLOPE", "");
    if (options.opening) defines.emplace_back("OPENING", "");
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
    prepare_boxes(p, in, framebuffer);
    if (clusters) {
        clusters->ranges.bind(cluster_range_texture_unit);
        clusters->cells.bind(cluster_cell_texture_unit);
    } else {
        cells.buffer.bind_base(GL_SHADER_STORAGE_BUFFER, primary_cells_binding);
    }
    draw_points(p, boxes);
}

void draw_opening_boxes(const gl::Program& p, const CutSurfaceInputs& in, const gl::Framebuffer& framebuffer,
                        const OpeningBoxes& boxes) {
    if (boxes.count == 0) return;
    prepare_boxes(p, in, framebuffer);
    boxes.cells.bind_base(GL_SHADER_STORAGE_BUFFER, opening_cells_binding);
    draw_points(p, boxes.count);
}

}  // namespace cutaway::pipeline

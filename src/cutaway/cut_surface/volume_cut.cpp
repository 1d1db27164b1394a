#include "cutaway/cut_surface/volume_cut.h"

#include <stdexcept>

#include "gl/uniforms.h"
#include "shapes/triangle_adjacency.h"

namespace cutaway::pipeline {

VolumeCut::VolumeCut(const gl::ShaderLibrary& shaders)
    : program_(shaders.build({{GL_VERTEX_SHADER, "cut_surface/volume.vert"},
                              {GL_GEOMETRY_SHADER, "cut_surface/volume.geom"},
                              {GL_FRAGMENT_SHADER, "cut_surface/volume.frag"}})) {}

void VolumeCut::set_volumes(const std::vector<shapes::TriangleMesh>& meshes, const ModelFrame& frame) {
    // Each triangle with the vertex across each edge (GL_TRIANGLES_ADJACENCY): the shader draws
    // walls only along the silhouette.
    std::vector<float> corners;
    for (const shapes::TriangleMesh& mesh : meshes) {
        for (const auto& triangle : mesh.triangles)
            for (std::uint32_t index : triangle)
                if (index >= mesh.positions.size()) throw std::invalid_argument("cut volume: triangle index out of range");
        for (const auto& six : shapes::triangle_adjacency(mesh))
            for (std::uint32_t index : six) {
                const glm::vec3 p = frame.to_render(mesh.positions[index]);
                corners.insert(corners.end(), {p.x, p.y, p.z});
            }
    }
    triangles_ = corners.size() / 18;
    // Triangles are wound outward in model coordinates; a mirroring model-to-render map (depth
    // positive down) turns them inward, which the shader's rear-face test must know.
    const glm::vec3 o = frame.to_render({0, 0, 0});
    const float det = glm::dot(frame.to_render({1, 0, 0}) - o,
                               glm::cross(frame.to_render({0, 1, 0}) - o, frame.to_render({0, 0, 1}) - o));
    outward_sign_ = det < 0 ? -1.0f : 1.0f;
    positions_ = corners.empty() ? gl::Buffer() : gl::Buffer::from(std::span<const float>(corners));
    glVertexArrayVertexBuffer(vertex_array_.id(), 0, positions_.id(), 0, GLsizei(3 * sizeof(float)));
    glEnableVertexArrayAttrib(vertex_array_.id(), 0);
    glVertexArrayAttribFormat(vertex_array_.id(), 0, 3, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(vertex_array_.id(), 0, 0);
}

void VolumeCut::draw(const CutSurfaceInputs& in, const CutTargets& targets) const {
    if (empty()) return;
    const Camera& camera = in.cut_camera;
    const gl::Program& p = program_;
    gl::set_uniform(p, "cut_view", camera.view);
    gl::set_uniform(p, "near_plane", camera.near_plane);
    gl::set_uniform(p, "far_plane", camera.far_plane);
    gl::set_uniform(p, "projection_scale", glm::vec2(camera.projection[0][0], camera.projection[1][1]));
    gl::set_uniform(p, "rim_depth", in.rim_depth);
    gl::set_uniform(p, "wall_angle", glm::vec2(in.wall_angle_h_rad, in.wall_angle_v_rad));
    gl::set_uniform(p, "outward_sign", outward_sign_);
    targets.framebuffer.bind();
    glViewport(0, 0, camera.width, camera.height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);
    // A volume reaching beyond the far plane cuts to it rather than being clipped open there.
    glEnable(GL_DEPTH_CLAMP);
    vertex_array_.bind();
    p.use();
    glDrawArrays(GL_TRIANGLES_ADJACENCY, 0, GLsizei(6 * triangles_));
    glDisable(GL_DEPTH_CLAMP);
    glDepthFunc(GL_LESS);
}

}  // namespace cutaway::pipeline

#include "cutaway/well_tubes.h"

#include <cstdint>
#include <stdexcept>

#include "common/shared_constants.h"
#include "gl/face_culling.h"
#include "shapes/tube_mesh.h"

namespace cutaway::pipeline {
namespace {

struct TubeVertex {
    float position[3];
    float normal[3];
    std::uint32_t well;
    std::uint8_t colour[4];
};

std::uint8_t channel(float value) { return std::uint8_t(glm::clamp(value, 0.0f, 1.0f) * 255.0f + 0.5f); }

}  // namespace

WellTubes::WellTubes(const gl::ShaderLibrary& shaders)
    : program_(shaders.build({{GL_VERTEX_SHADER, "primary/well.vert"}, {GL_FRAGMENT_SHADER, "primary/well.frag"}})) {
    const GLuint va = vertex_array_.id();
    for (GLuint a = 0; a < 4; ++a) {
        glEnableVertexArrayAttrib(va, a);
        glVertexArrayAttribBinding(va, a, 0);
    }
    glVertexArrayAttribFormat(va, 0, 3, GL_FLOAT, GL_FALSE, offsetof(TubeVertex, position));
    glVertexArrayAttribFormat(va, 1, 3, GL_FLOAT, GL_FALSE, offsetof(TubeVertex, normal));
    glVertexArrayAttribIFormat(va, 2, 1, GL_UNSIGNED_INT, offsetof(TubeVertex, well));
    glVertexArrayAttribFormat(va, 3, 4, GL_UNSIGNED_BYTE, GL_TRUE, offsetof(TubeVertex, colour));
}

void keep_wellheads_in_view(ModelFrame& frame, const WellSet& wells) {
    frame.drawn_with.clear();
    for (const DrawnWell& well : wells.wells)
        if (!well.path.empty()) frame.drawn_with.push_back(frame.to_render(well.path.front()));
}

void WellTubes::set(const WellSet& set, const ModelFrame& frame) {
    if (set.wells.size() > shared::max_drawn_wells)
        throw std::invalid_argument("wells: " + std::to_string(set.wells.size()) + " to draw, expected at most " +
                                    std::to_string(shared::max_drawn_wells));
    std::vector<TubeVertex> vertices;
    std::vector<std::uint32_t> indices;
    std::vector<WellHead> heads;
    for (std::size_t w = 0; w < set.wells.size(); ++w) {
        const DrawnWell& well = set.wells[w];
        std::vector<grid::Point3> render_path;
        for (const grid::Point3& p : well.path) {
            const glm::vec3 r = frame.to_render(p);
            render_path.push_back({r.x, r.y, r.z});
        }
        shapes::TriangleMesh mesh;
        try {
            mesh = shapes::tube_mesh(render_path, set.radius, shapes::tube_sides);
        } catch (const std::invalid_argument& e) {
            throw std::invalid_argument("well " + well.name + ": " + e.what());
        }
        const auto base = std::uint32_t(vertices.size());
        const std::uint8_t rgba[4] = {channel(well.colour.r), channel(well.colour.g), channel(well.colour.b), 255};
        for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
            const grid::Point3 &p = mesh.positions[v], &n = mesh.normals[v];
            vertices.push_back({{float(p.x), float(p.y), float(p.z)}, {float(n.x), float(n.y), float(n.z)}, std::uint32_t(w),
                                {rgba[0], rgba[1], rgba[2], rgba[3]}});
        }
        for (const auto& t : mesh.triangles) indices.insert(indices.end(), {base + t[0], base + t[1], base + t[2]});
        heads.push_back({well.name, well.colour, frame.to_render(well.path.front()), frame.to_render(well.path[1])});
    }
    vertices_ = vertices.empty() ? gl::Buffer() : gl::Buffer(vertices.size() * sizeof(TubeVertex), vertices.data());
    indices_ = indices.empty() ? gl::Buffer() : gl::Buffer(indices.size() * sizeof(std::uint32_t), indices.data());
    index_count_ = GLsizei(indices.size());
    heads_ = std::move(heads);
    if (index_count_ > 0) {
        glVertexArrayVertexBuffer(vertex_array_.id(), 0, vertices_.id(), 0, sizeof(TubeVertex));
        glVertexArrayElementBuffer(vertex_array_.id(), indices_.id());
    }
}

std::size_t WellTubes::memory_bytes() const { return vertices_.size_bytes() + indices_.size_bytes(); }

void WellTubes::draw(const Camera& camera, const CameraBlocks& cameras) const {
    if (empty()) return;
    cameras.bind_view(camera);
    glViewport(0, 0, camera.width, camera.height);
    // Tubes are closed and wound outward: their back faces are never seen.
    const gl::FaceCulling culling(GL_BACK);
    program_.use();
    vertex_array_.bind();
    glDrawElements(GL_TRIANGLES, index_count_, GL_UNSIGNED_INT, nullptr);
}

}  // namespace cutaway::pipeline

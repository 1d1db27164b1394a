#include "cutaway/exposed_surface.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "common/shared_constants.h"
#include "gl/compute_dispatch.h"
#include "gl/uniforms.h"

namespace cutaway::pipeline {
namespace {

enum ExposedSurfaceBinding : unsigned { corners_binding = shared::ssbo_face_corners };
/// Texture unit of the stored corners (common/face.vert STORED_CORNERS).
constexpr unsigned stored_corner_texture_unit = shared::tex_stored_corners;
constexpr std::size_t bytes_per_face = 12 * sizeof(float);

FaceBuffer checked_faces(const GridLayout& layout) {
    std::vector<std::uint32_t> records = exposed_faces(layout);
    // gl_VertexID / 4 indexes one bound range (GridBuffers::draw_faces: 2^27 faces), and the 4
    // corners of every face are texels of one buffer texture.
    GLint max_texels = 0;
    glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &max_texels);
    const std::size_t max_faces = std::min<std::size_t>(std::size_t(1) << 27, std::size_t(max_texels) / 4);
    if (records.size() > max_faces)
        throw std::invalid_argument("the model has " + std::to_string(records.size()) +
                                    " exposed faces; the plain frame draws at most " + std::to_string(max_faces));
    return FaceBuffer::from(records);
}

}  // namespace

ExposedSurface::ExposedSurface(const gl::ShaderLibrary& shaders, const GridBuffers& grid, const GridLayout& layout)
    : faces_(checked_faces(layout)),
      corners_(std::max<std::size_t>(faces_.count, 1) * bytes_per_face, nullptr),
      corner_texels_(corners_, GL_RGB32F) {
    const gl::Program store = shaders.build({{GL_COMPUTE_SHADER, "visibility/store_face_corners.comp"}});
    grid.set_geometry_uniforms(store);
    gl::set_uniform(store, "face_count", unsigned(faces_.count));
    grid.bind_geometry();
    faces_.buffer.bind_base(GL_SHADER_STORAGE_BUFFER, faces_binding);
    corners_.bind_base(GL_SHADER_STORAGE_BUFFER, corners_binding);
    store.use();
    const auto [groups_x, groups_y] = gl::dispatch_grid((faces_.count + 63) / 64);
    glDispatchCompute(groups_x, groups_y, 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
}

void ExposedSurface::draw(const GridBuffers& grid) const {
    corner_texels_.bind(stored_corner_texture_unit);
    grid.draw_faces(faces_);
}

}  // namespace cutaway::pipeline

#include "cutaway/camera_blocks.h"

#include <cstddef>
#include <cstring>

#include "common/shared_constants.h"

namespace cutaway::pipeline {

// The offsets std140 gives shaders/common/cameras.glsl's members.
static_assert(offsetof(ViewCameraBlock, eye) == 256 && offsetof(ViewCameraBlock, focal_px) == 268);
static_assert(offsetof(ViewCameraBlock, viewport_size) == 272 && offsetof(ViewCameraBlock, projection_scale) == 280);
static_assert(offsetof(ViewCameraBlock, near_plane) == 288 && offsetof(ViewCameraBlock, far_plane) == 292);
static_assert(offsetof(CutCameraBlock, ray_origin) == 192 && offsetof(CutCameraBlock, near_plane) == 204);
static_assert(offsetof(CutCameraBlock, ray_per_px) == 208 && offsetof(CutCameraBlock, size) == 240);
static_assert(offsetof(CutCameraBlock, far_plane) == 248);

namespace {
glm::vec2 projection_scale_of(const Camera& camera) { return {camera.projection[0][0], camera.projection[1][1]}; }

/// Uploads `contents` into `buffer` unless it holds them already; binds it at `binding`.
template <typename Block>
void upload_and_bind(const gl::Buffer& buffer, const Block& contents, Block& held, bool& uploaded, unsigned binding) {
    if (!uploaded || std::memcmp(&contents, &held, sizeof(Block)) != 0) {
        glNamedBufferSubData(buffer.id(), 0, sizeof(Block), &contents);
        held = contents;
        uploaded = true;
    }
    buffer.bind_base(GL_UNIFORM_BUFFER, binding);
}
}  // namespace

ViewCameraBlock ViewCameraBlock::of(const Camera& camera) {
    ViewCameraBlock b;
    b.view_projection = camera.view_projection();
    b.view = camera.view;
    b.inverse_view = glm::inverse(camera.view);
    b.inverse_view_projection = glm::inverse(b.view_projection);
    b.eye = camera.eye;
    b.focal_px = camera.focal_px();
    b.viewport_size = glm::vec2(float(camera.width), float(camera.height));
    b.projection_scale = projection_scale_of(camera);
    b.near_plane = camera.near_plane;
    b.far_plane = camera.far_plane;
    return b;
}

CutCameraBlock CutCameraBlock::of(const Camera& cut_camera) {
    CutCameraBlock b;
    b.view = cut_camera.view;
    b.projection = cut_camera.projection;
    b.view_projection = cut_camera.view_projection();
    // The eye-space ray (ndc / projection scale, -1) through window position w, ndc = 2 w / size - 1,
    // turned into world space: affine in w.
    const glm::mat3 to_world(glm::inverse(cut_camera.view));
    const glm::vec2 scale = projection_scale_of(cut_camera);
    b.size = glm::vec2(float(cut_camera.width), float(cut_camera.height));
    const glm::vec2 ndc_per_px = 2.0f / (b.size * scale);
    b.ray_origin = to_world * glm::vec3(-1.0f / scale, -1.0f);
    b.ray_per_px[0] = glm::vec4(to_world * glm::vec3(ndc_per_px.x, 0.0f, 0.0f), 0.0f);
    b.ray_per_px[1] = glm::vec4(to_world * glm::vec3(0.0f, ndc_per_px.y, 0.0f), 0.0f);
    b.near_plane = cut_camera.near_plane;
    b.far_plane = cut_camera.far_plane;
    return b;
}

CameraBlocks::CameraBlocks()
    : view_(sizeof(ViewCameraBlock), nullptr, GL_DYNAMIC_STORAGE_BIT),
      cut_(sizeof(CutCameraBlock), nullptr, GL_DYNAMIC_STORAGE_BIT) {}

void CameraBlocks::bind_view(const Camera& camera) const {
    upload_and_bind(view_, ViewCameraBlock::of(camera), view_held_, view_uploaded_, shared::ubo_view_camera);
}

void CameraBlocks::bind_cut(const Camera& cut_camera) const {
    upload_and_bind(cut_, CutCameraBlock::of(cut_camera), cut_held_, cut_uploaded_, shared::ubo_cut_camera);
}

}  // namespace cutaway::pipeline

#include "cutaway/frame_targets.h"

#include <array>

namespace cutaway::pipeline {

namespace {
const float zero[4] = {0, 0, 0, 0};
const GLuint zero_id[4] = {0, 0, 0, 0};
const float far_depth = 1.0f;
}  // namespace

CutTargets::CutTargets(int width, int height)
    : surface(GL_TEXTURE_2D, GL_R32F, width, height),
      rear_clamp(GL_TEXTURE_2D, GL_R8, width, height),
      depth(GL_TEXTURE_2D, GL_DEPTH_COMPONENT32F, width, height) {
    framebuffer.attach(GL_COLOR_ATTACHMENT0, surface);
    framebuffer.attach(GL_COLOR_ATTACHMENT1, rear_clamp);
    framebuffer.attach(GL_DEPTH_ATTACHMENT, depth);
    const std::array<GLenum, 2> buffers{GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    framebuffer.finish(buffers, "cut surface");
}

void CutTargets::clear() const {
    glClearNamedFramebufferfv(framebuffer.id(), GL_COLOR, 0, zero);
    glClearNamedFramebufferfv(framebuffer.id(), GL_COLOR, 1, zero);
    glClearNamedFramebufferfv(framebuffer.id(), GL_DEPTH, 0, zero);
}

SceneTargets::SceneTargets(int width, int height)
    : colour(GL_TEXTURE_2D, GL_RGBA8, width, height),
      normal_depth(GL_TEXTURE_2D, GL_RG32UI, width, height),
      id(GL_TEXTURE_2D, GL_RG32UI, width, height),
      face_plane(GL_TEXTURE_2D, GL_RG32UI, width, height),
      depth(GL_TEXTURE_2D, GL_DEPTH_COMPONENT32F, width, height),
      shell_depth(GL_TEXTURE_2D, GL_R32F, width, height),
      shell_depth_buffer(GL_TEXTURE_2D, GL_DEPTH_COMPONENT32F, width, height) {
    framebuffer.attach(GL_COLOR_ATTACHMENT0, colour);
    framebuffer.attach(GL_COLOR_ATTACHMENT1, normal_depth);
    framebuffer.attach(GL_COLOR_ATTACHMENT2, id);
    framebuffer.attach(GL_COLOR_ATTACHMENT3, face_plane);
    framebuffer.attach(GL_DEPTH_ATTACHMENT, depth);
    const std::array<GLenum, 4> buffers{GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2,
                                        GL_COLOR_ATTACHMENT3};
    framebuffer.finish(buffers, "scene");
    deferred_framebuffer.attach(GL_COLOR_ATTACHMENT2, id);
    deferred_framebuffer.attach(GL_COLOR_ATTACHMENT3, face_plane);
    deferred_framebuffer.attach(GL_DEPTH_ATTACHMENT, depth);
    const std::array<GLenum, 4> deferred_buffers{GL_NONE, GL_NONE, GL_COLOR_ATTACHMENT2, GL_COLOR_ATTACHMENT3};
    deferred_framebuffer.finish(deferred_buffers, "deferred scene");
    plain_framebuffer.attach(GL_COLOR_ATTACHMENT0, colour);
    plain_framebuffer.attach(GL_COLOR_ATTACHMENT2, id);
    plain_framebuffer.attach(GL_DEPTH_ATTACHMENT, depth);
    const std::array<GLenum, 3> plain_buffers{GL_COLOR_ATTACHMENT0, GL_NONE, GL_COLOR_ATTACHMENT2};
    plain_framebuffer.finish(plain_buffers, "plain scene");
    shell_framebuffer.attach(GL_COLOR_ATTACHMENT0, shell_depth);
    shell_framebuffer.attach(GL_DEPTH_ATTACHMENT, shell_depth_buffer);
    const std::array<GLenum, 1> shell_buffers{GL_COLOR_ATTACHMENT0};
    shell_framebuffer.finish(shell_buffers, "shell depth");
}

void SceneTargets::clear() const {
    // colour and face_plane are read only where id says a cell was drawn: not cleared (12 of the
    // G-buffer's 32 bytes per pixel; on llvmpipe at 1080p their clear was a noticeable cost).
    glClearNamedFramebufferuiv(framebuffer.id(), GL_COLOR, 1, zero_id);
    glClearNamedFramebufferuiv(framebuffer.id(), GL_COLOR, 2, zero_id);
    glClearNamedFramebufferfv(framebuffer.id(), GL_DEPTH, 0, &far_depth);
    glClearNamedFramebufferfv(shell_framebuffer.id(), GL_COLOR, 0, zero);
    glClearNamedFramebufferfv(shell_framebuffer.id(), GL_DEPTH, 0, &far_depth);
}

const NearestFaceTarget& SceneTargets::nearest_face() const {
    if (!nearest_face_) nearest_face_ = std::make_unique<NearestFaceTarget>(depth);
    return *nearest_face_;
}

NearestFaceTarget::NearestFaceTarget(const gl::Texture& scene_depth)
    : index(GL_TEXTURE_2D, GL_R32UI, scene_depth.width(), scene_depth.height()) {
    framebuffer.attach(GL_COLOR_ATTACHMENT0, index);
    framebuffer.attach(GL_DEPTH_ATTACHMENT, scene_depth);
    const std::array<GLenum, 1> buffers{GL_COLOR_ATTACHMENT0};
    framebuffer.finish(buffers, "nearest face");
}

void NearestFaceTarget::clear() const { glClearNamedFramebufferuiv(framebuffer.id(), GL_COLOR, 0, zero_id); }

void SceneTargets::clear_plain() const {
    glClearNamedFramebufferfv(plain_framebuffer.id(), GL_COLOR, 0, zero);
    glClearNamedFramebufferuiv(plain_framebuffer.id(), GL_COLOR, 2, zero_id);
    glClearNamedFramebufferfv(plain_framebuffer.id(), GL_DEPTH, 0, &far_depth);
}

PostTargets::PostTargets(int width, int height)
    : ambient(GL_TEXTURE_2D, GL_RG32F, width, height), final_colour(GL_TEXTURE_2D, GL_RGBA8, width, height) {
    const std::array<GLenum, 1> buffers{GL_COLOR_ATTACHMENT0};
    final_framebuffer.attach(GL_COLOR_ATTACHMENT0, final_colour);
    final_framebuffer.finish(buffers, "final image");
}

}  // namespace cutaway::pipeline

#include "cutaway/rear_shell_depth.h"

#include <array>

#include "cutaway/face_drawing.h"

namespace cutaway::pipeline {

RearShellDepth::RearShellDepth(const gl::ShaderLibrary& shaders, const CameraBlocks& cameras, int width, int height)
    // The seed shader writes exactly this: the cut camera's depth encoding, depth only.
    // Only back-facing triangles: where a ray leaves the closed outer surface it crosses a triangle
    // whose cell lies in front of it, so the farthest hit is always a back-facing one; culling the
    // front-facing ones halves what is rasterised and binned. The rasteriser decides per triangle
    // (common/face_corner.vert), so a warped face seen edge-on keeps the triangle where a ray
    // leaves the model (a face-wide test misjudged one and left a covered fault face,
    // grid/fault_cover.h, farthest at a few pixels).
    : cameras_(cameras),
      program_(shaders.build({{GL_VERTEX_SHADER, "common/face_corner.vert"}, {GL_FRAGMENT_SHADER, "cut_surface/seed_geometry.frag"}})),
      primaries_program_(shaders.build({{GL_VERTEX_SHADER, "common/face_corner.vert"}, {GL_FRAGMENT_SHADER, "cut_surface/far_depth.frag"}})) {
    allocate(width, height);
}

void RearShellDepth::resize(int width, int height) {
    if (width != depth_.width() || height != depth_.height()) allocate(width, height);
}

void RearShellDepth::allocate(int width, int height) {
    framebuffer_ = {};
    depth_ = {};  // the old image goes before the new one is allocated
    depth_ = gl::Texture(GL_TEXTURE_2D, GL_DEPTH_COMPONENT32F, width, height);
    framebuffer_.attach(GL_DEPTH_ATTACHMENT, depth_);
    const std::array<GLenum, 1> none{GL_NONE};
    framebuffer_.finish(none, "rear shell depth");
}

void RearShellDepth::render(const GridBuffers& grid, const Camera& cut_camera, bool primaries_drawn) {
    const float zero = 0.0f;
    glClearNamedFramebufferfv(framebuffer_.id(), GL_DEPTH, 0, &zero);
    framebuffer_.bind();
    prepare_face_program(program_, FaceDrawContext{grid, cut_camera, cameras_});
    set_depth_encoding(program_, cut_camera);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);
    glDepthMask(GL_TRUE);
    grid.draw_faces(grid.outer_faces(), GL_FRONT);
    if (primaries_drawn) {
        prepare_face_program(primaries_program_, FaceDrawContext{grid, cut_camera, cameras_});
        grid.draw_faces(grid.primary_faces());
    }
    glDepthFunc(GL_LESS);
}

}  // namespace cutaway::pipeline

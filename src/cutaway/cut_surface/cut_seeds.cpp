#include "cutaway/cut_surface/cut_seeds.h"

#include <array>

#include "cutaway/cut_surface/cell_boxes.h"
#include "cutaway/cut_surface/cut_depth_image.h"

namespace cutaway::pipeline {

CutSeedPass::CutSeedPass(const gl::ShaderLibrary& shaders) : program_(build_cell_box_program(shaders, true)) {}

cone_field::SeedImage CutSeedPass::render(const CutSurfaceInputs& inputs) {
    const Camera& camera = inputs.cut_camera;
    if (depth_.width() != camera.width || depth_.height() != camera.height) {
        depth_ = gl::Texture(GL_TEXTURE_2D, GL_DEPTH_COMPONENT32F, camera.width, camera.height);
        framebuffer_ = gl::Framebuffer();
        framebuffer_.attach(GL_DEPTH_ATTACHMENT, depth_);
        const std::array<GLenum, 1> none{GL_NONE};
        framebuffer_.finish(none, "cut seeds");
    }
    const float zero = 0.0f;
    glClearNamedFramebufferfv(framebuffer_.id(), GL_DEPTH, 0, &zero);
    draw_cell_boxes(program_, inputs, framebuffer_);

    cone_field::SeedImage seeds;
    seeds.depth = read_cut_depth_texture(depth_, camera);
    for (float& depth : seeds.depth.pixels)
        if (depth <= 0.0f) depth = cone_field::no_seed;
    return seeds;
}

}  // namespace cutaway::pipeline

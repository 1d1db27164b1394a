#include "cutaway/cut_surface/cut_seeds.h"

#include <algorithm>
#include <array>

#include "cutaway/cut_surface/cell_boxes.h"
#include "cutaway/cut_surface/cut_depth_image.h"
#include "cutaway/cut_surface/opening_cut.h"
#include "cutaway/face_drawing.h"

namespace cutaway::pipeline {

namespace {

/// Max over each pixel's 3x3 neighbourhood. A pixel centre exactly on a silhouette edge can be
/// covered by the cell's front face but not by the back face beside it (the two triangles share
/// the edge with opposite orientations, so the fill rule gives the pixel to only one); widening by
/// one pixel, as the box seeds are widened, keeps every primary pixel under a seed.
cone_field::SeedImage widened_by_one_pixel(const cone_field::SeedImage& seeds) {
    cone_field::SeedImage out = seeds;
    const int w = seeds.width(), h = seeds.height();
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float deepest = seeds.depth.at(x, y);
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    if (x + dx >= 0 && y + dy >= 0 && x + dx < w && y + dy < h)
                        deepest = std::max(deepest, seeds.depth.at(x + dx, y + dy));
            out.depth.at(x, y) = deepest;
        }
    return out;
}

}  // namespace

CutSeedPass::CutSeedPass(const gl::ShaderLibrary& shaders)
    : program_(build_cell_box_program(shaders, {.back_face_only = true})),
      geometry_program_(shaders.build({{GL_VERTEX_SHADER, "common/face_corner.vert"},
                                       {GL_FRAGMENT_SHADER, "cut_surface/seed_geometry.frag"}})) {}

const gl::Texture& CutSeedPass::render_on_gpu(const CutSurfaceInputs& inputs) {
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
    if (inputs.seeds == SeedSource::boxes) {
        draw_cell_boxes(program_, inputs, framebuffer_);
    } else {
        framebuffer_.bind();
        prepare_face_program(geometry_program_, FaceDrawContext{inputs.grid, camera, inputs.cameras});
        set_depth_encoding(geometry_program_, camera);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_GREATER);
        glDepthMask(GL_TRUE);
        inputs.grid.draw_faces(inputs.grid.primary_faces());
        glDepthFunc(GL_LESS);
    }
    if (inputs.openings) inputs.openings->draw_seeds(inputs, framebuffer_);
    if (inputs.combine_seeds) inputs.combine_seeds(depth_);  // a max: widening (a max filter) commutes with it
    return depth_;
}

cone_field::SeedImage CutSeedPass::render(const CutSurfaceInputs& inputs) {
    cone_field::SeedImage seeds;
    seeds.depth = read_cut_depth_texture(render_on_gpu(inputs), inputs.cut_camera);
    for (float& depth : seeds.depth.pixels)
        if (depth <= 0.0f) depth = cone_field::no_seed;
    if (needs_widening(inputs)) seeds = widened_by_one_pixel(seeds);
    return seeds;
}

}  // namespace cutaway::pipeline

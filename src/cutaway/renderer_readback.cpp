#include "cutaway/renderer_readback.h"

#include <bit>

#include "cutaway/cut_surface/cut_depth_image.h"
#include "cutaway/cut_surface/cut_seeds.h"
#include "gl/texture_readback.h"

namespace cutaway::pipeline {
namespace {

/// The float of an RG32UI target that holds a packed normal and a float per pixel
/// (shaders/common/packed_normal.glsl: its second word).
FloatImage read_packed_value(const gl::Texture& texture) {
    const std::vector<std::uint32_t> words = gl::read_texels<std::uint32_t>(texture, GL_RG_INTEGER, GL_UNSIGNED_INT, 2);
    FloatImage image{texture.width(), texture.height(), std::vector<float>(words.size() / 2)};
    for (std::size_t i = 0; i < image.values.size(); ++i) image.values[i] = std::bit_cast<float>(words[2 * i + 1]);
    return image;
}

}  // namespace


FacesDrawn FrameReadback::faces_drawn() const {
    FacesDrawn drawn = renderer_.last_drawn_;
    if (renderer_.visible_used_) {
        drawn.culling = renderer_.visible_.read_counts();
        drawn.secondary = drawn.culling->faces;
    }
    return drawn;
}

void FrameReadback::present(unsigned framebuffer, int x0, int y0, int x1, int y1) const {
    const bool same_size = x1 - x0 == renderer_.width_ && y1 - y0 == renderer_.height_;
    glBlitNamedFramebuffer(renderer_.post_.final_framebuffer.id(), framebuffer, 0, 0, renderer_.width_, renderer_.height_,
                           x0, y0, x1, y1, GL_COLOR_BUFFER_BIT, same_size ? GL_NEAREST : GL_LINEAR);
}

FloatImage FrameReadback::read_scene_depth() const { return read_packed_value(renderer_.scene_.normal_depth); }

FloatImage FrameReadback::read_cut_depth() const {
    const gl::Texture& surface = renderer_.cut_.surface;
    return {surface.width(), surface.height(), gl::read_texels<float>(surface, GL_RED, GL_FLOAT, 1)};
}

cone_field::FloatImage FrameReadback::read_strategy_cut(const Camera& camera) const {
    return read_cut_depth_texture(renderer_.cut_.depth, renderer_.cut_camera_for(camera));
}

cone_field::FloatImage RendererProbe::exact_cut(const FrameSettings& settings, const Camera& camera) const {
    return cpu_cone_cut(settings, camera, exact_cone_cut);
}

std::vector<std::uint32_t> RendererProbe::read_visible_faces() const { return renderer_.visible_.read_faces(); }

std::vector<float> RendererProbe::read_window_depth() const {
    return gl::read_texels<float>(renderer_.scene_.depth, GL_DEPTH_COMPONENT, GL_FLOAT, 1);
}

std::size_t RendererProbe::face_buffer_capacity() const { return renderer_.visible_.face_capacity(); }

void RendererProbe::set_face_buffer_capacity(std::size_t faces) const { probed_.visible_.set_capacity(faces); }

cone_field::FloatImage RendererProbe::cpu_cone_cut(const FrameSettings& settings, const Camera& camera,
                                                   const ConeFieldCut& cut) const {
    probed_.sync_selection_to_cpu();
    const CutSurfaceInputs inputs = probed_.cut_inputs(settings, probed_.cut_camera_for(camera));
    CutSeedPass seed_pass(probed_.shaders_);
    probed_.empty_vertex_array_.bind();
    return cone_field_cut_for(inputs, seed_pass.render(inputs), cut);
}

CutSurfaceInputs RendererProbe::cut_inputs(const FrameSettings& settings, const Camera& cut_camera) const {
    return renderer_.cut_inputs(settings, cut_camera);
}

}  // namespace cutaway::pipeline

#pragma once
// Images of the renderer's last frame read back from the GPU, apart from its production interface:
// FrameReadback holds what outputs and the image metrics read (the image, cell ids, depths, the
// cut), RendererProbe adds what
// tests and diagnostics look at (the culling's faces, the window depth, the face buffer's
// capacity, the CPU cone-field references behind `render --exact-check`).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "cone_field/cone_image.h"
#include "cutaway/cut_surface/cone_field_strategy.h"
#include "cutaway/cutaway_renderer.h"

namespace cutaway::pipeline {

class FrameReadback {
public:
    explicit FrameReadback(const CutawayRenderer& renderer) : renderer_(renderer) {}

    /// The last frame's final image (the PNG `render` writes), rows bottom to top.
    gl::RgbaImage read_image() const { return renderer_.read_image(); }
    /// Eclipse cell index + 1 of every pixel of the last frame (0: no cell), rows bottom to top.
    std::vector<std::uint32_t> read_eclipse_ids() const { return renderer_.read_eclipse_ids(); }

    /// Per-pixel ids read back: compact cell + 1 (0 = background) and flags (shared_constants.h).
    IdImage read_ids() const { return renderer_.read_ids(); }
    /// What the last frame (render or render_baseline) drew; the culling's counts are read back.
    FacesDrawn faces_drawn() const;
    /// Copies the last frame onto `framebuffer` (0: a window's) over the rectangle (x0, y0)-(x1, y1),
    /// scaled with linear filtering when the sizes differ.
    void present(unsigned framebuffer, int x0, int y0, int x1, int y1) const;
    /// Linear depth of the visible surface in the model camera (0 = background).
    FloatImage read_scene_depth() const;
    /// The cut surface used by the last frame: depth along the cut camera's axis (0 = no cut).
    FloatImage read_cut_depth() const;
    /// The strategy's cut of the last frame, before any mean filter: depth s along the cut
    /// camera's axis, rows top to bottom, 0 = nothing cut. `camera`: the frame's camera.
    cone_field::FloatImage read_strategy_cut(const Camera& camera) const;

protected:
    const CutawayRenderer& renderer_;
};

class RendererProbe : public FrameReadback {
public:
    explicit RendererProbe(CutawayRenderer& renderer) : FrameReadback(renderer), probed_(renderer) {}

    /// The face records stage 2 drew in the last visible-path frame, in drawing order.
    std::vector<std::uint32_t> read_visible_faces() const;
    /// The depth buffer of the last frame or plain frame (window depth 0..1, 1 = background),
    /// rows bottom to top.
    std::vector<float> read_window_depth() const;
    /// Records the culling's face buffer holds now, and a new size for it (it grows from there).
    std::size_t face_buffer_capacity() const;
    void set_face_buffer_capacity(std::size_t faces) const;
    /// The exact cone-field cut for `settings` and `camera` from the seeds and slope every
    /// cone-field strategy uses (cone_field_strategy.h), in read_strategy_cut's units.
    cone_field::FloatImage exact_cut(const FrameSettings& settings, const Camera& camera) const;
    /// The cone-field cut with any CPU cone-field function: the references of the GPU transforms.
    cone_field::FloatImage cpu_cone_cut(const FrameSettings& settings, const Camera& camera, const ConeFieldCut& cut) const;
    /// What stage 1 hands the strategy for `settings` and the cut camera (tests draw with it).
    CutSurfaceInputs cut_inputs(const FrameSettings& settings, const Camera& cut_camera) const;

private:
    CutawayRenderer& probed_;
};

}  // namespace cutaway::pipeline

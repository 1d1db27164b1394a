#include "cutaway/cutaway_renderer.h"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "cutaway/colour_map.h"
#include "cutaway/quantised_values.h"
#include "cutaway/cut_surface/cone_field_strategy.h"
#include "cutaway/cut_surface/cut_depth_image.h"
#include "cutaway/cut_surface/cut_seeds.h"
#include "cutaway/cut_surface/cut_strategy_choice.h"
#include "cutaway/cut_surface/cut_surface_registry.h"
#include "gl/gl_context.h"
#include "gl/gl_error.h"
#include "gl/texture_readback.h"
#include "grid/cell_geometry.h"
#include "grid/face_classification.h"

namespace cutaway::pipeline {
namespace {

/// The culling pass's buffers. Its bricks' boxes are the set-up's last read of the grid's corner
/// depths: `corner_depths_read` is called once they are built, before the buffers are allocated.
VisibleFaces make_visible_faces(const gl::ShaderLibrary& shaders, const grid::CornerPointGrid& grid,
                                const GridLayout& layout, const ModelFrame& frame,
                                const CutawayRenderer::CornerDepthsRead& corner_depths_read) {
    const CellBricks bricks = build_cell_bricks(grid, frame, corner_depths_read);
    // Sized ahead of time: up to 16M faces (64 MiB, models of about 5M cells) the buffer holds
    // every face the selection can pick, so no frame reads its count back. Above that, where
    // every buffer byte is resident memory on llvmpipe and a frame selects a small fraction of
    // the faces, it starts at an eighth of them and grows when a frame needs more (grow_to_fit).
    const std::size_t limit = selectable_face_capacity(layout);
    constexpr std::size_t whole_limit = std::size_t(1) << 24;
    return VisibleFaces(shaders, bricks, limit, limit <= whole_limit ? limit : limit / 8);
}

int checked_side(int side, const char* name) {
    const int limit = max_image_side();
    if (side < 1 || side > limit)
        throw std::invalid_argument(std::string("image ") + name + " " + std::to_string(side) +
                                    ": expected 1.." + std::to_string(limit) + " (this GL's texture/viewport limit)");
    return side;
}

/// Depth (along the view axis) of the nearest corner of the model's box: nothing lies in front
/// of it, so frustum walls stop there (and never nearer than the near plane).
float nearest_model_depth(const ModelFrame& frame, const Camera& camera) {
    float nearest = camera.far_plane;
    for (int c = 0; c < 8; ++c) {
        const glm::vec4 corner{c & 1 ? frame.render_max.x : frame.render_min.x, c & 2 ? frame.render_max.y : frame.render_min.y,
                               c & 4 ? frame.render_max.z : frame.render_min.z, 1.0f};
        nearest = std::min(nearest, -(camera.view * corner).z);
    }
    return std::max(nearest, camera.near_plane);
}

}  // namespace

int max_image_side() {
    GLint texture = 0, viewport[2] = {0, 0}, renderbuffer = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &texture);
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &renderbuffer);
    return std::min({texture, viewport[0], viewport[1], renderbuffer});
}

CutawayRenderer::CutawayRenderer(const gl::ShaderLibrary& shaders, const grid::CornerPointGrid& grid, double z_scale,
                                 int width, int height, const CornerDepthsRead& corner_depths_read)
    : CutawayRenderer(shaders, grid, grid::grid_bounds(grid), z_scale, width, height, corner_depths_read) {}

CutawayRenderer::CutawayRenderer(const gl::ShaderLibrary& shaders, const grid::CornerPointGrid& grid, const grid::Box3& bounds,
                                 double z_scale, int width, int height, const CornerDepthsRead& corner_depths_read)
    : CutawayRenderer(
          shaders, grid, make_model_frame(grid, bounds, z_scale),
          [&grid, tolerance = grid::face_tolerance_for(bounds)](const ModelFrame& frame) {
              return build_grid_layout(grid, grid::FaceClassification(grid, tolerance), frame);
          },
          width, height, corner_depths_read) {}

CutawayRenderer::CutawayRenderer(const gl::ShaderLibrary& shaders, const grid::CornerPointGrid& grid, const ModelFrame& frame,
                                 const grid::FaceClassification& classes, int width, int height,
                                 const CornerDepthsRead& corner_depths_read)
    : CutawayRenderer(
          shaders, grid, frame, [&](const ModelFrame& model_frame) { return build_grid_layout(grid, classes, model_frame); },
          width, height, corner_depths_read) {}

CutawayRenderer::CutawayRenderer(const gl::ShaderLibrary& shaders, const grid::CornerPointGrid& grid, const ModelFrame& frame,
                                 const LayOut& lay_out, int width, int height, const CornerDepthsRead& corner_depths_read)
    : shaders_(shaders),
      width_(checked_side(width, "width")),
      height_(checked_side(height, "height")),
      frame_(frame),
      layout_(lay_out(frame_)),
      grid_(grid),
      compact_of_cell_(grid.actnum()),
      buffers_(layout_, grid.zcorn(), frame_),
      visible_(make_visible_faces(shaders, grid, layout_, frame_, corner_depths_read)),
      selection_(shaders, layout_, grid),
      centroid_(shaders),
      colour_map_(make_colour_map_texture()),
      auto_sweep_from_(auto_sweep_from_primaries(gl::gl_renderer())),
      cut_(width, height),
      rear_shell_(shaders, cameras_, width, height),
      scene_(width, height),
      post_(width, height),
      secondary_(shaders),
      primary_(shaders),
      mean_filter_(shaders),
      cut_resolve_(shaders),
      volume_cut_(shaders),
      opening_cut_(shaders, frame_),
      ssao_(shaders),
      composite_(shaders),
      colour_bar_(shaders),
      wells_(shaders),
      well_labels_(shaders),
      frame_caption_(shaders) {
    // The GPU holds the pillars now: the CPU copy is not read again (compact_of_cell_ answers the
    // few Eclipse -> compact lookups a selection change needs, from ACTNUM).
    layout_.pillars = std::vector<float>();  // (= {} would keep the capacity)
    set_primaries(std::vector<std::uint8_t>(grid.cell_count(), 0));
    set_colouring(std::vector<float>(grid.cell_count(), 0.0f), {"", 0, 1, ""});
}

namespace {
/// Replaces per-pixel `targets` by a set of `width` x `height`, the old ones freed first (a 1 x 1
/// set stands in between), so the two sizes never hold memory at once.
template <class Targets>
void reallocate(Targets& targets, int width, int height) {
    targets = Targets(1, 1);
    targets = Targets(width, height);
}
}  // namespace

void CutawayRenderer::resize(int width, int height) {
    if (width == width_ && height == height_) return;
    width_ = checked_side(width, "width");
    height_ = checked_side(height, "height");
    reallocate(cut_, width_, height_);
    reallocate(scene_, width_, height_);
    reallocate(post_, width_, height_);
    rear_shell_.resize(width_, height_);
    freeze(std::nullopt);
}

void CutawayRenderer::set_colouring(const std::vector<float>& values, const ColourBarLabel& label, ValueStorage storage) {
    if (values.size() != grid_.cell_count())
        throw std::invalid_argument("colour values: " + std::to_string(values.size()) + ", expected one per cell");
    std::vector<float> compact(layout_.cells.size());
    for (std::size_t c = 0; c < compact.size(); ++c) compact[c] = values[layout_.cells[c] & 0x7fffffffu];
    if (storage == ValueStorage::unorm16) {
        buffers_.set_values(quantise_unorm16(compact));
        uploaded_bytes_ += compact.size() * sizeof(std::uint16_t);
    } else {
        buffers_.set_values(compact);
        uploaded_bytes_ += compact.size() * sizeof(float);
    }
    label_ = label;
}

float CutawayRenderer::colour_bar_reserved_width(const FrameSettings& settings) const {
    return settings.colour_bar ? annotation::colour_bar_reserved_width(label_, width_, height_) : 0.0f;
}

void CutawayRenderer::set_primaries(const std::vector<std::uint8_t>& flags) {
    if (flags.size() != grid_.cell_count())
        throw std::invalid_argument("primary flags: " + std::to_string(flags.size()) + " entries, expected one per cell");
    const std::vector<std::uint32_t> bits = primary_bits(layout_, flags);
    selection_.select_bits(buffers_, bits);
    uploaded_bytes_ += bits.size() * sizeof(std::uint32_t);
    selection_changed();
    primary_flags_ = flags;  // known here: no read-back needed
    set_primary_centroid();
    selection_on_cpu_ = true;
}

void CutawayRenderer::select_range(const grid::PrimaryRange& range, const std::optional<grid::IjkBox>& box) {
    if (buffers_.values_quantised())
        throw std::logic_error("primaries by range over 16-bit colouring values: set them with ValueStorage::float32");
    selection_.select_range(buffers_, range, box);
    selection_changed();
    // At selection time, not in a frame: the centroid (the cone slope's reference) and the count
    // (auto's choice) are sums the GPU reduces; the flags stay on the GPU unless a strategy reads them.
    set_primary_centroid();
}

void CutawayRenderer::sync_selection_to_cpu() {
    if (selection_on_cpu_) return;
    const std::vector<std::uint32_t> bits = buffers_.read_primary_bits();
    selection_readback_bytes_ += bits.size() * sizeof(std::uint32_t);
    primary_flags_ = pipeline::primary_flags(layout_, bits, grid_.cell_count());
    selection_on_cpu_ = true;
}

void CutawayRenderer::set_primary_centroid() {
    CentreSum centres = centroid_.centre_sum(buffers_);
    if (hooks_.sum_centres) centres = hooks_.sum_centres(centres);
    primary_centroid_ = centres.count ? glm::vec3(centres.sum / double(centres.count)) : glm::vec3(0);
    primaries_of_all_renderers_ = centres.count;
}

void CutawayRenderer::set_hooks(FrameHooks hooks) {
    hooks_ = std::move(hooks);
    visible_.reserve_limit();
}

void CutawayRenderer::select(const Primaries& primaries) {
    if (primaries.flags && primaries.flags->empty())
        set_primaries(std::vector<std::uint8_t>(grid_.cell_count(), 0));  // Primaries::none()
    else if (primaries.flags)
        set_primaries(*primaries.flags);
    else
        select_range(primaries.range, primaries.box);
}

void CutawayRenderer::set_cut_volumes(const std::vector<shapes::TriangleMesh>& meshes) {
    volume_cut_.set_volumes(meshes, frame_);
    frozen_valid_ = false;
}

void CutawayRenderer::set_cone_reference(const std::optional<glm::vec3>& point) {
    cone_reference_ = point;
    frozen_valid_ = false;
}

void CutawayRenderer::set_opening_cells(const std::vector<temporal::OpeningCell>& cells) {
    std::vector<CompactOpening> compact;
    compact.reserve(cells.size());
    for (const temporal::OpeningCell& cell : cells) {
        if (cell.cell >= grid_.cell_count() || !grid_.actnum()[cell.cell])
            throw std::invalid_argument("opening cell " + std::to_string(cell.cell) + ": expected an active cell");
        compact.push_back({compact_of_cell_(cell.cell), cell.opening, cell.beside_cut});
    }
    opening_cut_.set_cells(compact);
    uploaded_bytes_ += compact.size() * 2 * sizeof(std::uint32_t);
    frozen_valid_ = false;
}

void CutawayRenderer::set_wells(const WellSet& wells) {
    wells_.set(wells, frame_);
    keep_wellheads_in_view(frame_, wells);
}

void CutawayRenderer::freeze(const std::optional<Camera>& camera) {
    frozen_camera_ = camera;
    frozen_valid_ = false;
}

std::size_t RendererStatus::gpu_memory_bytes() const {
    std::size_t bytes = 0;
    for (const auto& [part, part_bytes] : gpu_memory_by_part) bytes += part_bytes;
    return bytes;
}

RendererStatus CutawayRenderer::status(const FrameSettings& settings) const {
    RendererStatus status;
    status.width = width_;
    status.height = height_;
    status.primary_cells = buffers_.primary_cells().count;
    status.cut_strategy = cut_strategy(settings);
    status.auto_sweep_from = auto_sweep_from_;
    status.colour_bar_reserved_width = colour_bar_reserved_width(settings);
    status.caption_reserved_height = caption_reserved_rows(settings.caption, width_, height_, status.colour_bar_reserved_width,
                                                           label_.min_text_px);
    status.frozen = frozen_camera_.has_value();
    status.frames_redrawn = frames_redrawn_;
    status.face_count_readback_bytes = visible_.count_readback_bytes();
    status.cut_readback_bytes = cut_readback_bytes_;
    status.selection_readback_bytes = selection_readback_bytes_;
    status.gpu_memory_by_part = {{"grid", buffers_.memory_bytes()},
                                 {"culling", visible_.memory_bytes()},
                                 {"selection", selection_.memory_bytes()},
                                 {"exposed_surface", exposed_ ? exposed_->memory_bytes() : 0},
                                 {"cut_volumes", volume_cut_.memory_bytes()},
                                 {"opening_cells", opening_cut_.memory_bytes()},
                                 {"wells", wells_.memory_bytes()}};
    status.last_plan = last_plan_;
    status.cut_volume_triangles = volume_cut_.triangle_count();
    status.well_heads = wells_.heads();
    status.uploaded_bytes = uploaded_bytes_;
    status.primary_centroid = primary_centroid_;
    return status;
}

std::string CutawayRenderer::cut_strategy(const FrameSettings& settings) const {
    return resolve_cut_strategy(settings.strategy, primaries_of_all_renderers_, auto_sweep_from_);
}

void CutawayRenderer::selection_changed() {
    ++selection_generation_;
    selection_on_cpu_ = false;
    secondary_list_built_ = false;
    frozen_valid_ = false;
}

const FaceBuffer& CutawayRenderer::secondary_face_list() {
    if (!secondary_list_built_) {
        sync_selection_to_cpu();
        buffers_.set_secondary_faces(build_face_lists(grid_, layout_, primary_flags_, true).secondary);
        secondary_list_built_ = true;
    }
    return buffers_.secondary_faces();
}

void CutawayRenderer::draw_secondary_faces(DrawMode draw) {
    if (draw == DrawMode::visible) {
        visible_.draw(buffers_);
        return;
    }
    buffers_.draw_faces(secondary_face_list());
}

CutSurfaceStrategy& CutawayRenderer::strategy(const std::string& name) {
    for (auto& [known, instance] : strategies_)
        if (known == name) return *instance;
    strategies_.emplace_back(name, find_cut_surface(name).make(shaders_));
    return *strategies_.back().second;
}

CutSurfaceInputs CutawayRenderer::cut_inputs(const FrameSettings& s, const Camera& cut_camera) const {
    // Each wall leans out by half the full opening angle.
    return {buffers_, cut_camera, cameras_, glm::radians(0.5f * std::clamp(s.aperture_h_deg, 0.0f, 180.0f)),
            glm::radians(0.5f * std::clamp(s.aperture_v_deg, 0.0f, 180.0f)), s.back_margin * frame_.radius(),
            nearest_model_depth(frame_, cut_camera),
            std::max(-(cut_camera.view * glm::vec4(cone_reference_.value_or(primary_centroid_), 1.0f)).z, cut_camera.near_plane),
            s.seeds,
            {&primary_flags_, &compact_of_cell_, grid_.dims(), selection_generation_},
            {},
            opening_cut_.empty() ? nullptr : &opening_cut_};
}

float CutawayRenderer::rear_margin(const Camera& camera) const {
    // Far enough in front of the shell that its own fragments (the same faces, rasterised again)
    // stay behind the clamp despite rounding: 1e-4 of the model's radius, plus 64 steps of the
    // 32-bit depth encoding over the camera's depth range (which dominates for tiny models: 1e-5
    // of the radius left 11 pixels in front of the cut on a 6-cell grid).
    return 1e-4f * float(frame_.radius()) + 4e-6f * (camera.far_plane - camera.near_plane);
}

void CutawayRenderer::resolve_cut(const gl::FloatImageBuffer* filtered, const FrameSettings& s, const Camera& cut_camera) {
    const gl::Texture* rear_shell = s.see_through ? nullptr : &rear_shell_.depth();
    if (filtered) cut_resolve_.apply(*filtered, cut_, cut_camera, rear_shell, rear_margin(cut_camera));
    else cut_resolve_.apply(cut_, cut_camera, rear_shell, rear_margin(cut_camera));
}

const gl::Texture& CutawayRenderer::render_view_rear_shell(const Camera& camera, bool primaries_drawn) {
    // The frozen cut was resolved against the frozen camera's rear shell already: the texture is
    // free until the cut is made again.
    rear_shell_.render(buffers_, camera, primaries_drawn);
    if (hooks_.combine_max) hooks_.combine_max({&rear_shell_.depth()});
    return rear_shell_.depth();
}

FrameTimes CutawayRenderer::render(const FrameSettings& s, const Camera& camera, Fencing fencing) {
    timer_.set_fenced(fencing == Fencing::each_stage);
    struct FencesBack {  // stages are fenced again after this frame, even when it throws
        gl::StageTimer& timer;
        ~FencesBack() { timer.set_fenced(true); }
    } fences_back{timer_};
    FrameTimes times = render_once(s, camera);
    // After the frame's fence: the culling's 4-byte face count says whether its buffer was too
    // small (faces were dropped). The grown buffer fits this frame's selection, so once is enough.
    if (visible_used_ && visible_.grow_to_fit()) {
        ++frames_redrawn_;
        times = render_once(s, camera);
    }
    return times;
}

RendererState CutawayRenderer::state_for(const CutSurfaceEntry& strategy) const {
    RendererState state;
    state.frozen = frozen_camera_.has_value();
    state.frozen_cut_valid = frozen_valid_;
    state.cone_field_strategy = bool(strategy.cpu_reference);
    state.cut_volumes = !volume_cut_.empty();
    state.opening_cells = !opening_cut_.empty();
    state.distributed = bool(hooks_.combine_max);
    state.screen_passes = hooks_.screen_passes;
    state.wells = !wells_.empty();
    return state;
}

FrameTimes CutawayRenderer::render_once(const FrameSettings& s, const Camera& camera) {
    if (camera.width != width_ || camera.height != height_)
        throw std::invalid_argument("camera image size differs from the renderer's");
    const CutSurfaceEntry strategy = find_cut_surface(cut_strategy(s));
    // Untimed, once per GPU selection, and only for a strategy that builds from the flags.
    if (strategy.selection_on_cpu) sync_selection_to_cpu();
    last_plan_ = plan_frame(s, state_for(strategy));
    timer_.clear();
    cut_readback_bytes_ = 0;
    empty_vertex_array_.bind();
    glFinish();
    const auto started = std::chrono::steady_clock::now();

    const FrameStep step{s, camera, cut_camera_for(camera), last_plan_};
    for (const PlannedStage& stage : last_plan_.stages) {
        empty_vertex_array_.bind();  // attribute-less passes draw with it; each pass binds its own otherwise
        const auto run = [&] {
            for (FramePass pass : stage.passes) run_pass(pass, step);
        };
        if (stage.stage.empty()) run();
        else gl::timed_stage(timer_, stage.stage, run);
    }
    if (last_plan_.makes_cut) frozen_valid_ = frozen_camera_.has_value();
    glFinish();
    last_drawn_ = {};
    last_drawn_.secondary = last_plan_.runs(FramePass::secondary_list) ? buffers_.secondary_faces().count : 0;
    last_drawn_.primary = last_plan_.draw_primaries ? buffers_.primary_faces().count : 0;
    last_drawn_.shell_contours = s.contours ? buffers_.outer_faces().count() : 0;
    visible_used_ = last_plan_.runs(FramePass::culling);
    FrameTimes times;
    times.stages = timer_.stages();
    times.total.stage = "total";
    times.total.wall_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
    times.total.gl_query_valid = true;
    for (const gl::StageTime& stage : times.stages) {
        times.total.gl_query_ms += stage.gl_query_ms;
        times.total.gl_query_valid = times.total.gl_query_valid && stage.gl_query_valid;
    }
    return times;
}

void CutawayRenderer::run_pass(FramePass pass, const FrameStep& f) {
    gl::DebugGroup group(to_string(pass));
    switch (pass) {
    case FramePass::clear_cut: cut_.clear(); return;
    case FramePass::strategy_cut: draw_strategy_cut(f); return;
    case FramePass::volume_cut: volume_cut_.draw(cut_inputs(f.settings, f.cut_camera), cut_); return;
    case FramePass::opening_cut: opening_cut_.draw(cut_inputs(f.settings, f.cut_camera), cut_); return;
    case FramePass::rear_shell: rear_shell_.render(buffers_, f.cut_camera, f.plan.draw_primaries); return;
    case FramePass::combine_cut: {
        std::vector<const gl::Texture*> images;
        if (f.plan.combine_cut_depth) images.push_back(&cut_.depth);
        if (f.plan.combine_rear_shell) images.push_back(&rear_shell_.depth());
        hooks_.combine_max(images);
        return;
    }
    case FramePass::resolve_cut: resolve_cut(nullptr, f.settings, f.cut_camera); return;
    case FramePass::filter_resolve_cut:
        resolve_cut(&mean_filter_.filter(cut_, f.settings.mean_filter | 1, f.settings.mean_filter_kernel, f.cut_camera,
                                         mean_filter_reference_depth(frame_, f.cut_camera)),
                    f.settings, f.cut_camera);
        return;
    case FramePass::culling:
        visible_.select(buffers_, cameras_, f.camera, f.plan.cut_drawn ? &cut_ : nullptr, f.cut_camera, f.plan.clip_view_rear_shell);
        return;
    case FramePass::secondary_list: secondary_face_list(); return;
    case FramePass::view_rear_shell: render_view_rear_shell(f.camera, f.plan.draw_primaries); return;
    case FramePass::clear_scene:
        scene_.clear();
        scene_.framebuffer.bind();
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(f.settings.depth_ties_to_last ? GL_LEQUAL : GL_LESS);
        return;
    case FramePass::secondaries: draw_secondaries(f); return;
    case FramePass::bind_scene: scene_.framebuffer.bind(); return;
    case FramePass::primaries: primary_.draw_primaries(draw_context(f.camera), buffers_.primary_faces(), f.settings); return;
    case FramePass::hidden_primary_walls: primary_.draw_hidden_walls(draw_context(f.camera), buffers_.primary_faces()); return;
    case FramePass::wells: wells_.draw(f.camera, cameras_); return;
    case FramePass::shell_contours: primary_.draw_shell_depth(draw_context(f.camera), scene_); return;
    case FramePass::reset_depth_test: glDepthFunc(GL_LESS); return;
    case FramePass::combine_scene: hooks_.combine_scene(scene_); return;
    case FramePass::ssao:
        ssao_.apply(scene_, post_, f.camera, f.settings, f.settings.ssao_radius * frame_.radius(),
                    f.plan.cut_drawn && same_view(f.camera, f.cut_camera) ? &cut_.surface : nullptr);
        return;
    case FramePass::composite:
        composite_.apply(scene_, post_, f.settings, width_, height_);
        empty_vertex_array_.bind();
        return;
    case FramePass::colour_bar:
        colour_bar_.draw(post_.final_framebuffer, width_, height_, colour_map_, label_,
                         f.settings.saturation ? std::optional<BarSaturation>({f.settings.saturation_primary,
                                                                                f.settings.saturation_secondary})
                                               : std::nullopt);
        empty_vertex_array_.bind();
        return;
    case FramePass::well_labels:
        well_labels_.draw(post_.final_framebuffer, wells_.heads(), f.camera, colour_bar_reserved_width(f.settings),
                          label_.min_text_px, f.settings.caption);
        empty_vertex_array_.bind();
        return;
    case FramePass::caption:
        frame_caption_.draw(post_.final_framebuffer, width_, height_, f.settings.caption, colour_bar_reserved_width(f.settings),
                            label_.min_text_px);
        empty_vertex_array_.bind();
        return;
    }
}

FaceDrawContext CutawayRenderer::draw_context(const Camera& camera) const {
    return {buffers_, camera, cameras_, &colour_map_, {label_.min, label_.max}, label_.log_scale};
}

void CutawayRenderer::draw_strategy_cut(const FrameStep& f) {
    CutSurfaceStrategy& cut_strategy = strategy(this->cut_strategy(f.settings));
    CutSurfaceInputs inputs = cut_inputs(f.settings, f.cut_camera);
    if (f.plan.combine_seeds) inputs.combine_seeds = [&](const gl::Texture& seeds) { hooks_.combine_max({&seeds}); };
    cut_strategy.render(inputs, cut_);
    cut_readback_bytes_ = cut_strategy.readback_bytes();
}

void CutawayRenderer::draw_secondaries(const FrameStep& f) {
    // The view's rear shell was drawn by view_rear_shell earlier in this stage (freeze view).
    const CutClip clip{cut_, f.cut_camera, cameras_, f.plan.clip_view_rear_shell ? &rear_shell_.depth() : nullptr,
                       rear_margin(f.camera)};
    secondary_.draw(draw_context(f.camera), [&] { draw_secondary_faces(f.settings.draw); }, f.settings, clip, scene_,
                    f.settings.draw);
}

gl::StageTime CutawayRenderer::render_baseline(const Camera& camera, DrawMode draw) {
    timer_.clear();
    empty_vertex_array_.bind();
    const FrameSettings plain;  // its line width
    // Built on first use, untimed: every face of every cell, or the exposed faces with their corners.
    if (draw == DrawMode::all_faces) buffers_.all_faces();
    if (draw == DrawMode::visible && !exposed_) exposed_.emplace(shaders_, buffers_, layout_);
    const FaceDrawContext context = draw_context(camera);
    gl::timed_stage(timer_, "baseline", [&] {
        scene_.clear_plain();
        scene_.plain_framebuffer.bind();
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        const auto submit = [&] {
            if (draw == DrawMode::visible) exposed_->draw(buffers_);
            else buffers_.draw_faces(buffers_.all_faces());
        };
        secondary_.draw_plain(context, submit, plain, draw);
    });
    frozen_valid_ = false;
    last_drawn_ = {};
    last_drawn_.secondary = draw == DrawMode::all_faces ? buffers_.all_faces().count : exposed_->face_count();
    visible_used_ = false;
    return timer_.stages().back();
}


gl::RgbaImage CutawayRenderer::read_image() const {
    return gl::read_rgba(post_.final_framebuffer.id(), 0, width_, height_);
}

IdImage CutawayRenderer::read_ids() const {
    const std::vector<std::uint32_t> pairs = gl::read_texels<std::uint32_t>(scene_.id, GL_RG_INTEGER, GL_UNSIGNED_INT, 2);
    IdImage ids{width_, height_, {}, {}};
    ids.cell.resize(pairs.size() / 2);
    ids.flags.resize(pairs.size() / 2);
    for (std::size_t i = 0; i < ids.cell.size(); ++i) {
        ids.cell[i] = pairs[2 * i];
        ids.flags[i] = pairs[2 * i + 1];
    }
    return ids;
}

std::vector<std::uint32_t> CutawayRenderer::read_eclipse_ids() const {
    std::vector<std::uint32_t> ids = read_ids().cell;
    for (std::uint32_t& id : ids)
        if (id != 0) id = (layout_.cells[id - 1] & 0x7fffffffu) + 1;
    return ids;
}

}  // namespace cutaway::pipeline

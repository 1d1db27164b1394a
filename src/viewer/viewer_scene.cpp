#include "viewer/viewer_scene.h"

#include <utility>

#include "app_core/frame_wells.h"
#include "app_core/step_value_sources.h"
#include "cutaway/camera.h"
#include "grid/cell_geometry.h"
#include "grid/primary_selection.h"

namespace cutaway::viewer {

ViewerScene::ViewerScene(app::LoadedModel model, const gl::ShaderLibrary& shaders, const app::RenderOptions& options,
                         int width, int height)
    : model_(std::move(model)),
      shaders_(shaders),
      z_scale_(options.z_scale),
      primaries_(options.frame_settings().primaries),
      volume_options_(options.cut_volumes),
      memory_limit_bytes_(options.model_memory_limit_bytes()),
      bounds_(grid::grid_bounds(model_.grid)) {
    select(options);
    rebuild_renderer(width, height, options.frame_settings());
}

void ViewerScene::select(const app::RenderOptions& options) {
    // Holding another report step releases the array shown now: the shown values stay valid (a
    // copy) in case the new selection is refused.
    if (!app::holds_time_step(model_, options.property, options.step) && property_.external)
        property_.owned = *std::exchange(property_.external, nullptr);
    app::hold_property(model_, options.property, options.step, options.model_memory_limit_bytes());
    app::PropertyChoice property = app::choose_property(model_.grid, options);
    // A restart's wells change with the report step; a file's stay (read again when --wells changes).
    if (wells_step_ == -2 || (options.step != wells_step_ && model_.report_steps) || options.wells != wells_values_) {
        wells_ = app::frame_wells(model_, options.wells, options.well_radius, options.step);
        if (wells_step_ == -2) volume_wells_ = app::cut_volume_well_paths(model_, options.wells, options.step);
        wells_step_ = options.step;
        wells_values_ = options.wells;
        if (renderer_) renderer_->set_wells(wells_);
    }
    std::optional<grid::IjkBox> box = app::choose_primary_range(model_.grid, property, options);
    // A new range over the same values re-uploads nothing: the renderer selects on the GPU.
    const bool same_values = renderer_ && property.label == property_.label;
    if (!same_values) histogram_ = active_histogram(model_.grid, property.values(), histogram_bins);
    property_ = std::move(property);
    options_colour_range_ = options.colour_range;
    box_ = box;
    if (!renderer_) return;
    if (!same_values) apply_colouring(*renderer_);
    select_primaries(*renderer_);
}

void ViewerScene::select_primaries(pipeline::CutawayRenderer& renderer) const {
    renderer.set_opening_cells({});  // a played frame's cells still opening belong to that frame
    if (primaries_)
        renderer.select({property_.primary_range, box_});
    else
        renderer.select(pipeline::Primaries::none());
    renderer.mark_primary_range(property_.colour_bar_label(primaries_).primary_range);
}

void ViewerScene::rebuild_renderer(int width, int height, const pipeline::FrameSettings& settings) {
    auto renderer = std::make_unique<pipeline::CutawayRenderer>(shaders_, model_.grid, z_scale_, width, height);
    if (!cut_volumes_)
        cut_volumes_ = app::load_cut_volumes(volume_options_, renderer->frame(), volume_wells_, memory_limit_bytes_);
    renderer->set_cut_volumes(cut_volumes_->meshes);
    apply_selection(*renderer);
    // One frame compiles every program the settings use, so a broken shader fails here and the
    // previous renderer stays.
    renderer->render(settings, pipeline::make_orbit_camera(renderer->frame(), {}, width, height));
    renderer_ = std::move(renderer);
}

void ViewerScene::set_cut_volumes(const std::vector<volumes::CutVolume>& list) {
    app::CutVolumeSet set = app::build_cut_volumes(list, renderer_->frame(), volume_wells_, memory_limit_bytes_);
    renderer_->set_cut_volumes(set.meshes);
    cut_volumes_ = std::move(set);
}

std::vector<std::string> ViewerScene::well_names() const {
    std::vector<std::string> names;
    for (const auto& [name, path] : volume_wells_) names.push_back(name);
    return names;
}

void ViewerScene::apply_selection(pipeline::CutawayRenderer& renderer) const {
    renderer.set_wells(wells_);
    apply_colouring(renderer);
    select_primaries(renderer);
}

void ViewerScene::apply_colouring(pipeline::CutawayRenderer& renderer) const {
    renderer.set_colouring(property_.values(), property_.colour_bar_label(primaries_));
}

std::size_t ViewerScene::primary_count() const { return renderer_ ? renderer_->status().primary_cells : 0; }

std::size_t ViewerScene::step_count() const {
    if (model_.report_steps && model_.report_steps->has_property(property_.name)) return model_.report_steps->step_count();
    return model_.grid.step_count(property_.name);
}

const std::vector<eclipse::ReportStep>& ViewerScene::report_steps() const {
    static const std::vector<eclipse::ReportStep> none;
    return model_.report_steps ? model_.report_steps->steps() : none;
}

std::unique_ptr<StepPlayer> ViewerScene::player(temporal::Coherence coherence, std::size_t frames_per_step,
                                                std::size_t start_step) {
    // animate's --hysteresis default: a primary stays until it leaves the range widened by 2% of the span.
    constexpr float hysteresis = 0.02f;
    const PlaybackSettings settings{coherence, frames_per_step, property_.primary_range,
                              coherence == temporal::Coherence::smooth
                                  ? hysteresis * (property_.colour_range.max - property_.colour_range.min)
                                  : 0.0f,
                              box_};
    std::unique_ptr<temporal::StepValueSource> source = app::step_values_of(model_, property_.name);
    // One colour scale for every played step (--colour-range, else the values' span over all of
    // them): a step's own percentiles would recolour the front as it moves.
    playing_colours_ = property_.colour_bar_label(primaries_);
    playing_colours_.property = property_.name;  // the overlay shows the date and step
    if (options_colour_range_.empty()) {
        const grid::PrimaryRange span = temporal::value_range_over_steps(model_.grid, *source, 0, source->step_count() - 1);
        playing_colours_.min = span.min;
        playing_colours_.max = span.max;
    }
    return std::make_unique<StepPlayer>(model_.grid, std::move(source), settings, start_step);
}

void ViewerScene::show(const temporal::CoherentSequence::Frame& frame) {
    if (frame.values_changed) renderer_->set_colouring(*frame.values, playing_colours_);
    renderer_->select(*frame.flags);
    renderer_->set_opening_cells(*frame.openings);
}

}  // namespace cutaway::viewer

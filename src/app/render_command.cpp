// `cutaway render MODEL [options] --out IMG.png [--stats STATS.json]`: one headless cutaway frame
// with per-stage fenced times and image metrics (DESIGN.md contract).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <utility>

#include "app/commands.h"
#include "app/distributed_render.h"
#include "app_core/frame_wells.h"
#include "app/mpi_launch.h"
#include "app_core/model_source.h"
#include "app_core/option_checks.h"
#include "app_core/render_options.h"
#include "app_core/render_report.h"
#include "app_core/run_context.h"
#include "app_core/run_context_json.h"
#include "annotation/colour_bar_layout.h"
#include "cutaway/cell_id_image.h"
#include "cutaway/cut_surface/cut_surface_registry.h"
#include "cutaway/cutaway_renderer.h"
#include "cutaway/frame_metrics.h"
#include "cutaway/renderer_readback.h"
#include "gl/gl_context.h"
#include "gl/image.h"
#include "metrics/cut_error.h"
#include "grid/primary_selection.h"
#include "io/output_batch.h"
#include "metrics/median.h"

namespace cutaway::app {
namespace {

using nlohmann::json;

/// The last frame's cut against the exact cone field from the same seeds (SPEC section 2).
json exact_check(pipeline::CutawayRenderer& renderer, const pipeline::FrameSettings& settings,
                 const pipeline::Camera& camera) {
    const cone_field::FloatImage cut = pipeline::FrameReadback(renderer).read_strategy_cut(camera);
    const auto started = std::chrono::steady_clock::now();
    const cone_field::FloatImage exact = pipeline::RendererProbe(renderer).exact_cut(settings, camera);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    const metrics::CutErrorOptions compare_options;
    const metrics::CutError error = metrics::compare_cut(cut, exact, compare_options);
    return {{"wrong_fraction", error.wrong_fraction}, {"tolerance", error.tolerance},
            {"relative_tolerance", compare_options.relative_tolerance}, {"mean_abs_error", error.mean_abs_error},
            {"max_abs_error", error.max_abs_error}, {"max_signed_error", error.max_signed_error},
            {"min_signed_error", error.min_signed_error}, {"pixels_compared", error.pixels_compared},
            {"pixels_wrong", error.pixels_wrong}, {"units", "depth along the cut camera's axis, render units"},
            {"exact_seconds", seconds}};
}

/// `options` for the colouring property: --step belongs to the --select-by property when that one
/// is dynamic and the colouring one is static (`--select-by SWAT --step 3` colours by PORO).
RenderOptions colouring_options(const grid::CornerPointGrid& grid, const RenderOptions& options) {
    RenderOptions colouring = options;
    const bool selection_dynamic = !options.select_by.empty() && grid.step_count(options.select_by) > 0;
    const bool colouring_static = options.property.empty() ? !grid.property_names().empty()
                                                           : grid.step_count(options.property) == 0;
    if (selection_dynamic && colouring_static) colouring.step = -1;
    return colouring;
}

/// Faces each pass drew, frames drawn again, the cut's read-back and the culling's counts.
void add_draw_counts(json& stats, const pipeline::CutawayRenderer& renderer) {
    stats["faces_drawn"] = faces_drawn_json(pipeline::FrameReadback(renderer).faces_drawn());
    // Frames drawn twice because the culling's face buffer grew (cutaway_renderer.h render).
    stats["frames_redrawn"] = renderer.status().frames_redrawn;
    // Per frame (every timed frame reads back the same amount): 0 for the strategies on the GPU.
    stats["readback_bytes"] = renderer.status().cut_readback_bytes;
    if (stats["faces_drawn"].contains("culling")) {
        stats["bricks_culled"] = stats["faces_drawn"]["culling"]["bricks_culled"];
        stats["cells_culled"] = stats["faces_drawn"]["culling"]["cells_culled"];
    }
}

/// The same frame unfenced (a user's frame), against the exact cut (--exact-check) and the plain
/// frame of the whole model (--baseline).
void add_extra_frames(json& stats, const RenderOptions& options, pipeline::CutawayRenderer& renderer,
                      const pipeline::FrameSettings& settings, const pipeline::Camera& camera) {
    std::vector<double> unfenced;
    for (int i = 0; i < options.repeat; ++i)
        unfenced.push_back(renderer.render(settings, camera, pipeline::Fencing::frame_only).total.wall_ms);
    stats["frame_ms_unfenced"] = metrics::median(unfenced);
    if (options.exact_check) stats["cut_vs_exact"] = exact_check(renderer, settings, camera);
    if (options.baseline) {
        std::vector<double> baseline;
        for (int i = 0; i < std::max(1, options.repeat); ++i)
            baseline.push_back(renderer.render_baseline(camera, settings.draw).wall_ms);
        stats["baseline_ms"] = metrics::median(baseline);
        stats["baseline_faces_drawn"] = pipeline::FrameReadback(renderer).faces_drawn().secondary;
        stats["total_over_baseline"] = stats["stages_ms"]["total"].get<double>() / metrics::median(baseline);
    }
}

/// The image metrics of the frame (3 extra untimed frames).
void add_frame_metrics(json& stats, pipeline::CutawayRenderer& renderer, const pipeline::FrameSettings& settings,
                       const pipeline::Camera& camera) {
    const pipeline::FrameMetrics m = pipeline::measure_frame(renderer, settings, camera);
    put_metric(stats, "primary_exposure", m.exposure.fraction, m.exposure.primary_pixels,
               "no primary pixel in the primaries-only frame");
    stats["primary_pixels"] = m.exposure.primary_pixels;
    put_metric(stats, "context_kept", m.context.fraction, m.context.uncut - std::min(m.context.uncut, m.context.kept_180),
               "the 180-degree-aperture frame keeps as much context as the uncut frame");
    stats["context_pixels"] = {{"cutaway", m.context.kept}, {"aperture_180", m.context.kept_180},
                               {"uncut", m.context.uncut}};
    stats["border_line_width"] = {{"mean_px", m.border_width.mean}, {"stddev_px", m.border_width.stddev},
                                  {"pixels", m.border_width.pixels}};
    stats["secondary_pixels_in_front_of_cut"] = m.secondary_in_front;
}

/// Peak resident memory and the GPU buffers by part, beside the phases' resident memory.
void add_memory_use(json& memory, const pipeline::CutawayRenderer& renderer, const RenderOptions& options) {
    memory["peak_resident"] = run_context::proc_status_bytes("VmHWM");
    memory["gpu_buffers"] = renderer.status().gpu_memory_bytes();
    json by_part = json::object();
    for (const auto& [part, bytes] : renderer.status().gpu_memory_by_part) by_part[part] = bytes;
    memory["gpu_buffers_by_part"] = by_part;
    memory["render_target_budget"] = options.render_target_bytes();
}

/// A simulator case's report step (and any INIT array not read yet) for what the frame shows.
void hold_frame_properties(LoadedModel& model, const RenderOptions& options) {
    hold_property(model, options.property, options.step, options.model_memory_limit_bytes());
    if (!options.select_by.empty()) hold_property(model, options.select_by, options.step, options.model_memory_limit_bytes());
}

/// The frame's camera beside the colour bar; with --freeze-camera the frozen cut's camera set.
pipeline::Camera frame_camera(pipeline::CutawayRenderer& renderer, const pipeline::FrameSettings& settings,
                              const RenderOptions& options) {
    // Framed beside the colour bar and below the caption (a case's report step), if any.
    const pipeline::RendererStatus status = renderer.status(settings);
    const float bar_width = status.colour_bar_reserved_width, caption_rows = status.caption_reserved_height;
    if (options.freeze_pose)
        renderer.freeze(pipeline::make_orbit_camera(renderer.frame(), *options.freeze_pose, options.width, options.height, bar_width,
                                                    0, caption_rows));
    return pipeline::make_orbit_camera(renderer.frame(), options.camera_pose(), options.width, options.height, bar_width, 0,
                                       caption_rows);
}

/// --warmup untimed frames, then --repeat timed ones.
std::vector<pipeline::FrameTimes> timed_frames(pipeline::CutawayRenderer& renderer, const pipeline::FrameSettings& settings,
                                               const pipeline::Camera& camera, const RenderOptions& options) {
    for (int i = 0; i < options.warmup; ++i) renderer.render(settings, camera);
    std::vector<pipeline::FrameTimes> runs;
    for (int i = 0; i < options.repeat; ++i) runs.push_back(renderer.render(settings, camera));
    return runs;
}

/// The image and --cell-ids, staged in `outputs`.
void stage_images(io::OutputBatch& outputs, const pipeline::CutawayRenderer& renderer, const RenderOptions& options) {
    outputs.write(options.out, gl::encode_png(pipeline::FrameReadback(renderer).read_image(), options.out));
    if (!options.cell_ids.empty())
        outputs.write(options.cell_ids,
                      gl::encode_png(pipeline::encode_cell_ids(pipeline::FrameReadback(renderer).read_eclipse_ids(), options.width, options.height),
                                     options.cell_ids));
}

/// Says on stderr that the primary range holds no cell (the frame shows the context only).
void warn_without_primaries(std::size_t primary_count, const std::string& name, const grid::PrimaryRange& range) {
    if (primary_count == 0)
        std::cerr << "cutaway render: no cell of " << name << " lies in the primary range [" << range.min << ", "
                  << range.max << "]; rendering the context only\n";
}

/// The model's and the image's sizes and where the memory went, in stats.json.
void add_model_facts(json& stats, const LoadedModel& model, const RenderOptions& options, std::size_t primary_count,
                     const json& memory) {
    stats["size"] = {options.width, options.height};
    stats["cells"] = model.grid.cell_count();
    stats["active_cells"] = model.grid.active_count();
    stats["primary_cells"] = primary_count;
    stats["memory_bytes"] = memory;
    stats["model"] = model.description;
    stats["model_load_s"] = model.load_seconds;
}

/// The frame's primaries: none (`--primaries none`), by a second property, or the range and box.
void select_primaries(pipeline::CutawayRenderer& renderer, bool primaries, const PropertyChoice& property,
                      const std::optional<SecondPropertySelection>& selected_by, const std::optional<grid::IjkBox>& box) {
    if (!primaries)
        renderer.select(pipeline::Primaries::none());
    else if (selected_by)
        renderer.select(selected_by->flags);
    else
        renderer.select({property.primary_range, box});
}

/// The colour bar's box in image pixels, rows from the top: what an image check leaves out of the model.
json colour_bar_box(const annotation::ColourBarLabel& label, const RenderOptions& options) {
    const annotation::PixelRect bar = annotation::layout_colour_bar(label, options.width, options.height).bounds();
    return {bar.x0, bar.y0, bar.x1, bar.y1};
}

int run_render(const RenderOptions& options) {
    if (launched_by_mpi()) return run_distributed_render(options);
    refuse_render_overwrites(options);
    LoadedModel model =
        load_model(options.model, options.model_memory_limit_bytes(), property_to_load(options), render_outputs(options));
    hold_frame_properties(model, options);
    // Paths need the corner depths, which the renderer releases once it has built its geometry.
    const pipeline::WellSet wells = frame_wells(model, options.wells, options.well_radius, options.step);
    const volumes::WellPaths volume_wells = cut_volume_well_paths(model, options.wells, options.step);
    // Where the memory goes (bytes resident after each phase; on llvmpipe GPU memory is host memory).
    json memory{{"resident_after_load", run_context::proc_status_bytes("VmRSS")}};
    PropertyChoice property = choose_property(model.grid, colouring_options(model.grid, options));
    const std::optional<grid::IjkBox> box = choose_primary_range(model.grid, property, options);
    const std::optional<SecondPropertySelection> selected_by = select_by_second_property(model.grid, options);
    pipeline::FrameSettings settings = options.frame_settings();
    if (options.caption) settings.caption = step_caption(model, property.name, options.step);
    // One frame needs one array: keep it, drop the others (36 bytes per cell for a generated model).
    if (property.external) property.owned = *std::exchange(property.external, nullptr);
    model.grid.clear_properties();
    std::unique_ptr<gl::GlContext> context = gl::create_context(options.context_options());
    const gl::ShaderLibrary shaders(gl::ShaderLibrary::default_root());
    const auto setup_started = std::chrono::steady_clock::now();
    // The corner depths live on the GPU once the geometry is built: released there, before the
    // selection, the render targets and the colouring are allocated (the set-up's peak holds one).
    pipeline::CutawayRenderer renderer(shaders, model.grid, options.z_scale, options.width, options.height,
                                       [&model] { model.grid.release_corner_depths(); });
    check_view(renderer.frame(), options);
    renderer.set_wells(wells);
    const CutVolumeSet cut_volumes =
        load_cut_volumes(options.cut_volumes, renderer.frame(), volume_wells, options.model_memory_limit_bytes());
    renderer.set_cut_volumes(cut_volumes.meshes);
    const bool primaries = settings.primaries;
    const annotation::ColourBarLabel label = property.colour_bar_label(!selected_by && primaries);
    renderer.set_colouring(property.values(), label);
    select_primaries(renderer, primaries, property, selected_by, box);
    // The values live on the GPU now (colouring and selection); the frames read no CPU copy.
    property.owned = std::vector<float>();
    glFinish();
    const double setup_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - setup_started).count();
    memory["resident_after_setup"] = run_context::proc_status_bytes("VmRSS");
    const std::size_t primary_count = renderer.status().primary_cells;
    const std::string selected_name = selected_by ? selected_by->label : property.label;
    const grid::PrimaryRange selected_range = selected_by ? selected_by->range : property.primary_range;
    refuse_nothing_to_draw(options, primary_count, selected_name, selected_range);
    if (primaries) warn_without_primaries(primary_count, selected_name, selected_range);
    const pipeline::Camera camera = frame_camera(renderer, settings, options);
    const std::vector<pipeline::FrameTimes> runs = timed_frames(renderer, settings, camera, options);
    const std::vector<std::string> frame_plan = renderer.status().last_plan.describe();  // before the metrics' frames
    memory["resident_after_frames"] = run_context::proc_status_bytes("VmRSS");
    // Committed together once the stats are written too: a failed --stats leaves no image behind.
    io::OutputBatch outputs;
    stage_images(outputs, renderer, options);

    json stats = stage_statistics(runs);
    add_draw_counts(stats, renderer);
    const pipeline::CutSurfaceEntry strategy = pipeline::find_cut_surface(renderer.status(settings).cut_strategy);
    stats["cut_device"] = strategy.device;
    add_extra_frames(stats, options, renderer, settings, camera);
    if (options.metrics) add_frame_metrics(stats, renderer, settings, camera);
    stats["strategy"] = strategy_json(strategy, settings.strategy, renderer.status().auto_sweep_from);
    stats.update(run_context_json(current_gl_device(context->platform())));
    add_memory_use(memory, renderer, options);
    add_model_facts(stats, model, options, primary_count, memory);
    stats["gpu_memory_bytes"] = renderer.status().gpu_memory_bytes();
    stats["renderer_setup_s"] = setup_seconds;  // geometry built and uploaded, colouring and selection set
    stats["property"] = {{"name", property.label}, {"colour_range", {property.colour_range.min, property.colour_range.max}},
                         {"colour_scale", property.log_scale ? "log" : "linear"}, {"selected_by", selected_name}, {"primary_range", {selected_range.min, selected_range.max}},
                         {"caption", settings.caption}};  // the report step drawn over the frame (empty: none)
    if (settings.colour_bar) stats["colour_bar_box"] = colour_bar_box(label, options);
    stats["configuration"] = options.describe();
    stats["configuration"]["cut_volumes"] = cut_volumes.describe();
    stats["plan"] = frame_plan;
    stats["warmup"] = options.warmup;
    stats["repeat"] = options.repeat;
    if (!options.stats.empty()) outputs.write(options.stats, stats.dump(2) + '\n');
    outputs.commit();
    std::cout << "cutaway render: " << options.out << " (" << primary_count << " primary cells, total "
              << stats["stages_ms"]["total"].get<double>() << " ms median of " << options.repeat << ")\n";
    return 0;
}

}  // namespace

CommandAction add_render_command(CLI::App& app) {
    auto options = std::make_shared<RenderOptions>();
    CLI::App* command = app.add_subcommand("render", "Render one headless cutaway frame with per-stage times and metrics");
    add_render_options(*command, *options);
    return [options] { return run_render(*options); };
}

}  // namespace cutaway::app

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
#include "app/mpi_launch.h"
#include "app/model_source.h"
#include "app/option_checks.h"
#include "app/render_options.h"
#include "app/render_report.h"
#include "app/run_context.h"
#include "app/run_context_json.h"
#include "cutaway/cell_id_image.h"
#include "cutaway/cut_surface/cut_surface_registry.h"
#include "cutaway/cutaway_renderer.h"
#include "cutaway/frame_metrics.h"
#include "gl/gl_context.h"
#include "gl/image.h"
#include "metrics/cut_error.h"
#include "grid/primary_selection.h"
#include "io/staged_file.h"
#include "metrics/median.h"

namespace cutaway::app {
namespace {

using nlohmann::json;

/// The last frame's cut against the exact cone field from the same seeds (SPEC section 2).
json exact_check(pipeline::CutawayRenderer& renderer, const pipeline::FrameSettings& settings,
                 const pipeline::Camera& camera) {
    const cone_field::FloatImage cut = renderer.read_strategy_cut(camera);
    const auto started = std::chrono::steady_clock::now();
    const cone_field::FloatImage exact = renderer.exact_cut(settings, camera);
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

int run_render(const RenderOptions& options) {
    if (launched_by_mpi()) return run_distributed_render(options);
    // Inputs first: an output naming a model file would overwrite it.
    std::vector<std::pair<std::string, std::string>> files;
    for (const std::string& model : options.model) files.emplace_back("the model", model);
    files.insert(files.end(), {{"--out", options.out}, {"--stats", options.stats}, {"--cell-ids", options.cell_ids}});
    refuse_shared_outputs(files);
    LoadedModel model = load_model(options.model, options.model_memory_limit_bytes(), property_to_load(options));
    // Where the memory goes (bytes resident after each phase; on llvmpipe GPU memory is host memory).
    json memory{{"resident_after_load", run_context::proc_status_bytes("VmRSS")}};
    PropertyChoice property = choose_property(model.grid, options);
    const std::optional<grid::IjkBox> box = choose_primary_range(model.grid, property, options);
    const std::optional<SecondPropertySelection> selected_by = select_by_second_property(model.grid, options);
    // One frame needs one array: keep it, drop the others (36 bytes per cell for a generated model).
    if (property.external) property.owned = *std::exchange(property.external, nullptr);
    model.grid.clear_properties();
    const grid::CornerPointGrid& grid = model.grid;

    std::unique_ptr<gl::GlContext> context = gl::create_context(options.context_options());
    const gl::ShaderLibrary shaders(gl::ShaderLibrary::default_root());
    const auto setup_started = std::chrono::steady_clock::now();
    // The corner depths live on the GPU once the geometry is built and nothing reads them on the
    // CPU again: released there, before the selection, the render targets and the colouring are
    // allocated, so the set-up's peak does not hold both.
    pipeline::CutawayRenderer renderer(shaders, grid, options.z_scale, options.width, options.height,
                                       [&model] { model.grid.release_corner_depths(); });
    check_view(renderer.frame(), options);
    renderer.set_colouring(property.values(), property.colour_bar_label(!selected_by));
    if (selected_by)
        renderer.set_primaries(selected_by->flags);
    else
        renderer.select_range(property.primary_range, box);
    // The values live on the GPU now (colouring and selection); the frames read no CPU copy.
    property.owned = std::vector<float>();
    glFinish();
    const double setup_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - setup_started).count();
    memory["resident_after_setup"] = run_context::proc_status_bytes("VmRSS");
    const std::size_t primary_count = renderer.primary_cell_count();
    const std::string selected_name = selected_by ? selected_by->label : property.label;
    const grid::PrimaryRange selected_range = selected_by ? selected_by->range : property.primary_range;
    if (primary_count == 0)
        std::cerr << "cutaway render: no cell of " << selected_name << " lies in the primary range ["
                  << selected_range.min << ", " << selected_range.max << "]; rendering the context only\n";
    const pipeline::FrameSettings settings = options.frame_settings();
    const float bar_width = renderer.colour_bar_reserved_width(settings);
    const pipeline::Camera camera =
        pipeline::make_orbit_camera(renderer.frame(), options.camera_pose(), options.width, options.height, bar_width);
    if (options.freeze_pose)
        renderer.freeze(pipeline::make_orbit_camera(renderer.frame(), *options.freeze_pose, options.width, options.height, bar_width));

    for (int i = 0; i < options.warmup; ++i) renderer.render(settings, camera);
    std::vector<pipeline::FrameTimes> runs;
    for (int i = 0; i < options.repeat; ++i) runs.push_back(renderer.render(settings, camera));
    memory["resident_after_frames"] = run_context::proc_status_bytes("VmRSS");
    gl::write_png(renderer.read_image(), options.out);
    if (!options.cell_ids.empty())
        gl::write_png(pipeline::encode_cell_ids(renderer.read_eclipse_ids(), options.width, options.height), options.cell_ids);

    json stats = stage_statistics(runs);
    stats["faces_drawn"] = faces_drawn_json(renderer.faces_drawn());
    // Frames drawn twice because the culling's face buffer grew (cutaway_renderer.h render).
    stats["frames_redrawn"] = renderer.frames_redrawn();
    // Per frame (every timed frame reads back the same amount): 0 for the strategies on the GPU.
    stats["readback_bytes"] = renderer.cut_readback_bytes();
    const pipeline::CutSurfaceEntry strategy = pipeline::find_cut_surface(renderer.cut_strategy(settings));
    stats["cut_device"] = strategy.device;
    if (stats["faces_drawn"].contains("culling")) {
        stats["bricks_culled"] = stats["faces_drawn"]["culling"]["bricks_culled"];
        stats["cells_culled"] = stats["faces_drawn"]["culling"]["cells_culled"];
    }
    std::vector<double> unfenced;
    for (int i = 0; i < options.repeat; ++i) unfenced.push_back(renderer.render_unfenced_ms(settings, camera));
    stats["frame_ms_unfenced"] = metrics::median(unfenced);
    if (options.exact_check) stats["cut_vs_exact"] = exact_check(renderer, settings, camera);
    if (options.baseline) {
        std::vector<double> baseline;
        for (int i = 0; i < std::max(1, options.repeat); ++i)
            baseline.push_back(renderer.render_baseline(camera, settings.draw).wall_ms);
        stats["baseline_ms"] = metrics::median(baseline);
        stats["baseline_faces_drawn"] = renderer.faces_drawn().secondary;
        stats["total_over_baseline"] = stats["stages_ms"]["total"].get<double>() / metrics::median(baseline);
    }
    if (options.metrics) {
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
    stats["strategy"] = strategy_json(strategy, settings.strategy, renderer.auto_sweep_from());
    stats.update(run_context_json(current_gl_device(context->platform())));
    stats["size"] = {options.width, options.height};
    stats["cells"] = grid.cell_count();
    stats["active_cells"] = grid.active_count();
    stats["primary_cells"] = primary_count;
    stats["gpu_memory_bytes"] = renderer.gpu_memory_bytes();
    memory["peak_resident"] = run_context::proc_status_bytes("VmHWM");
    memory["gpu_buffers"] = renderer.gpu_memory_bytes();
    json by_part = json::object();
    for (const auto& [part, bytes] : renderer.gpu_memory_by_part()) by_part[part] = bytes;
    memory["gpu_buffers_by_part"] = by_part;
    memory["render_target_budget"] = options.render_target_bytes();
    stats["memory_bytes"] = memory;
    stats["model"] = model.description;
    stats["model_load_s"] = model.load_seconds;
    stats["renderer_setup_s"] = setup_seconds;  // geometry built and uploaded, colouring and selection set
    stats["property"] = {{"name", property.label}, {"colour_range", {property.colour_range.min, property.colour_range.max}},
                         {"colour_scale", property.log_scale ? "log" : "linear"}, {"selected_by", selected_name}, {"primary_range", {selected_range.min, selected_range.max}}};
    stats["configuration"] = options.describe();
    stats["warmup"] = options.warmup;
    stats["repeat"] = options.repeat;
    if (!options.stats.empty()) io::write_file(options.stats, stats.dump(2) + '\n');
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

// `cutaway volume CUBE.sgy [--tf grey|pseudo|layer] [--camera AZ EL DIST] [--size W H]
//  [--caster gpu|cpu] [--step S] [--no-skip] ... --out IMG.png [--stats STATS.json]`
#include <algorithm>
#include <cfloat>
#include <chrono>
#include <iostream>
#include <map>
#include <memory>
#include <stdexcept>
#include <thread>

#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "app_core/heap_policy.h"
#include "app_core/option_checks.h"
#include "app_core/run_context.h"
#include "app_core/run_context_json.h"
#include "gl/gl_context.h"
#include "gl/image.h"
#include "gl/shader_library.h"
#include "gl/stage_timer.h"
#include "io/output_batch.h"
#include "io/path_text.h"
#include "annotation/colour_bar_layout.h"
#include "volume/annotations.h"
#include "volume/colour_bar.h"
#include "volume/cpu_ray_caster.h"
#include "volume/gpu_ray_caster.h"
#include "volume/level_window.h"
#include "volume/segy_reader.h"
#include "volume/view_geometry.h"
#include "metrics/median.h"

namespace cutaway::app {
namespace {
using metrics::median;

using Clock = std::chrono::steady_clock;
using volume::RayCastSettings;

/// Host bytes a frame needs per pixel: the entry/exit float targets and the image on the GPU side
/// (host memory on llvmpipe) and the read-back; measured peak about 45 bytes per pixel
/// (volume --size 8192 8192: 3.0 GB).
constexpr std::size_t volume_target_bytes_per_pixel = 48;

struct VolumeOptions {
    std::string cube;
    std::string out;
    std::string stats;
    std::string tf = "grey";
    std::string caster = "gpu";
    std::vector<double> camera;
    std::vector<int> size;
    std::vector<double> layer;  ///< k r alpha_v f_v; empty: fitted to the window
    std::string window = "auto";       ///< auto (2-98 percentile levels) or full (0..255)
    std::string colour_scale = "perceptual";
    double opacity = volume::TransferFunctionSettings{}.opacity;
    bool no_skip = false, no_jitter = false, no_opacity_correction = false, no_early_termination = false;
    bool no_colour_bar = false;
    unsigned threads = 0;
    int warmup = 1;
    int repeat = 1;
    double memory_limit_gb = default_memory_limit_gib;
    volume::SegyReadOptions read;
    RayCastSettings settings;
};

double elapsed_ms(Clock::time_point since) {
    return std::chrono::duration<double, std::milli>(Clock::now() - since).count();
}

/// Per-stage times over the timed repetitions: fenced wall and GL query, ms.
struct StageSeries {
    std::vector<double> wall_ms, gl_query_ms;
    bool gl_query_valid = true;
};

/// Times and counts of the timed frames, plus the last frame.
struct FrameRuns {
    std::map<std::string, StageSeries> stages;
    std::vector<double> total_ms;
    volume::CastResult last;
    GlDevice gl_device{"none (cpu caster)", "", ""};
};

FrameRuns run_gpu(const volume::VolumeScene& scene, const VolumeOptions& options) {
    FrameRuns runs;
    const auto context = gl::create_context(gl::ContextOptions{});
    runs.gl_device = current_gl_device(context->platform());
    const gl::ShaderLibrary shaders(gl::ShaderLibrary::default_root());
    volume::GpuRayCaster caster(shaders, scene);
    for (int frame = 0; frame < options.warmup + options.repeat; ++frame) {
        gl::StageTimer timer;
        runs.last = caster.render(options.settings, timer);
        if (frame < options.warmup) continue;
        double total = 0;
        for (const gl::StageTime& stage : timer.stages()) {
            StageSeries& series = runs.stages[stage.stage];
            series.wall_ms.push_back(stage.wall_ms);
            series.gl_query_ms.push_back(stage.gl_query_ms);
            series.gl_query_valid = series.gl_query_valid && stage.gl_query_valid;
            total += stage.wall_ms;
        }
        runs.total_ms.push_back(total);
    }
    return runs;
}

FrameRuns run_cpu(const volume::VolumeScene& scene, const VolumeOptions& options) {
    FrameRuns runs;
    for (int frame = 0; frame < options.warmup + options.repeat; ++frame) {
        const Clock::time_point start = Clock::now();
        runs.last = volume::cast_rays_cpu(scene, options.settings, options.threads);
        const double ms = elapsed_ms(start);
        if (frame < options.warmup) continue;
        runs.stages["ray_cast"].wall_ms.push_back(ms);
        runs.total_ms.push_back(ms);
    }
    return runs;
}

nlohmann::json configuration_json(const VolumeOptions& o, const volume::TransferFunctionSettings& tf,
                                   const volume::ViewGeometry& view, unsigned threads) {
    const RayCastSettings& s = o.settings;
    return {{"caster", o.caster},
            {"transfer_function",
             {{"name", volume::transfer_function_name(tf.kind)},
              {"opacity", tf.opacity},
              {"window", o.window},
              {"window_levels", {tf.window.lo, tf.window.hi}},
              {"colour_scale", volume::colour_scale_name(tf.scale)},
              {"layer", {{"k", tf.layer.k}, {"r", tf.layer.r}, {"alpha_v", tf.layer.alpha_v}, {"f_v", tf.layer.f_v}}}}},
            {"size", {s.width, s.height}},
            {"camera",
             {{"azimuth_deg", s.camera.azimuth_deg},
              {"elevation_deg", s.camera.elevation_deg},
              {"distance", view.distance},
              {"fov_deg", s.camera.fov_deg}}},
            {"time_scale", view.time_scale},
            {"step_voxels", s.step},
            {"opacity_correction", s.opacity_correction},
            {"jitter", s.jitter},
            {"early_termination", s.early_termination},
            {"early_termination_alpha", s.early_termination_alpha},
            {"empty_space_skipping", s.empty_space_skipping},
            {"block_size", s.block_size},
            {"colour_bar", s.colour_bar},
            {"reserved_right_px", s.reserved_right_px},
            {"reserved_left_px", s.reserved_left_px},
            {"text_height_px", s.text_height_px},
            {"cpu_threads", threads},
            {"warmup", o.warmup},
            {"repeat", o.repeat},
            {"null_value", o.read.null_value}};
}

nlohmann::json input_json(const volume::VolumeCube& cube, const volume::QuantisedVolume& levels) {
    return {{"path", cube.source},
            {"dims", {cube.dims.inlines, cube.dims.crosslines, cube.dims.samples}},
            {"inline_range", {cube.inline_numbers.front(), cube.inline_numbers.back()}},
            {"crossline_range", {cube.crossline_numbers.front(), cube.crossline_numbers.back()}},
            {"sample_interval_ms", cube.sample_interval_ms},
            {"format", cube.format_name},
            {"byte_order", cube.little_endian ? "little-endian" : "big-endian"},
            {"sorting", volume::sorting_name(cube.sorting)},
            {"missing_traces", cube.missing_traces.size()},
            {"value_range", {levels.range.min, levels.range.max}}};
}

void apply_options(VolumeOptions& o, volume::TransferFunctionSettings& tf) {
    RayCastSettings& s = o.settings;
    if (!o.size.empty()) {
        s.width = o.size[0];
        s.height = o.size[1];
    }
    if (!o.camera.empty()) s.camera = {o.camera[0], o.camera[1], o.camera[2], s.camera.fov_deg};
    s.empty_space_skipping = !o.no_skip;
    s.jitter = !o.no_jitter;
    s.opacity_correction = !o.no_opacity_correction;
    s.early_termination = !o.no_early_termination;
    s.colour_bar = !o.no_colour_bar;
    if (o.caster != "gpu" && o.caster != "cpu")
        throw std::invalid_argument("volume: --caster " + o.caster + ": expected gpu or cpu");
    if (o.warmup < 0 || o.repeat < 1)
        throw std::invalid_argument("volume: --warmup must be >= 0 and --repeat >= 1");
    volume::validate(s);
    tf.kind = volume::parse_transfer_function(o.tf);
    tf.scale = volume::parse_colour_scale(o.colour_scale);
    tf.opacity = o.opacity;
    if (!o.layer.empty()) tf.layer = {o.layer[0], o.layer[1], o.layer[2], o.layer[3]};
    // One budget: the frame's targets first, the cube's samples from what is left.
    const std::size_t limit = gib_to_bytes(o.memory_limit_gb);
    const std::size_t target_bytes = std::size_t(s.width) * std::size_t(s.height) * volume_target_bytes_per_pixel;
    if (target_bytes > limit)
        throw std::invalid_argument("--size: " + memory_limit_problem(target_bytes, limit,
                                                                       "a frame of " + std::to_string(s.width) + " x " +
                                                                           std::to_string(s.height) + " pixels"));
    o.read.memory_limit_bytes = limit - target_bytes;
}

/// The largest share of a survey's traces that may be missing (filled with --null-value): beyond
/// it the image shows the null value almost everywhere.
constexpr double max_missing_trace_fraction = 0.9;

/// Refuses a cube whose image would be blank: almost every trace missing, or every sample equal
/// (one transfer-function level throughout).
void refuse_blank_cube(const volume::VolumeCube& cube, const volume::QuantisedVolume& levels) {
    const std::size_t traces = std::size_t(cube.dims.inlines) * std::size_t(cube.dims.crosslines);
    if (double(cube.missing_traces.size()) > max_missing_trace_fraction * double(traces))
        throw std::invalid_argument(io::shown_path(cube.source) + ": expected a survey with at least " +
                                    number_text(100 * (1 - max_missing_trace_fraction)) + "% of its traces present, found " +
                                    std::to_string(cube.missing_traces.size()) + " of " + std::to_string(traces) + " missing");
    if (!(levels.range.max > levels.range.min))
        throw std::invalid_argument(io::shown_path(cube.source) + ": expected amplitudes that vary, found every sample equal to " +
                                    number_text(levels.range.min) + " (the image would be blank)");
}

/// An eye inside the cube sees nothing but the voxels around it (a blank image in practice).
void refuse_eye_inside(const volume::ViewGeometry& view) {
    const glm::vec3& eye = view.eye_voxel;
    if (eye.x >= 0 && eye.y >= 0 && eye.z >= 0 && eye.x <= view.box.x && eye.y <= view.box.y && eye.z <= view.box.z)
        throw std::invalid_argument("--camera: expected DIST 0 (frame the cube) or an eye outside the cube, found DIST " +
                                    number_text(view.distance) + " (the eye is inside the cube)");
}

/// A cube so far away that it covers less than a pixel either way: the frame would hold nothing
/// but the colour bar.
void refuse_cube_under_a_pixel(const volume::ViewGeometry& view, int width, int height) {
    glm::vec2 low(FLT_MAX), high(-FLT_MAX);
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 voxel(corner & 1 ? view.box.x : 0.0f, corner & 2 ? view.box.y : 0.0f, corner & 4 ? view.box.z : 0.0f);
        const glm::vec4 clip = view.voxel_to_clip * glm::vec4(voxel, 1.0f);
        if (!(clip.w > 0)) return;  // a corner beside or behind the eye: the cube is near, not far
        low = glm::min(low, glm::vec2(clip) / clip.w);
        high = glm::max(high, glm::vec2(clip) / clip.w);
    }
    const double across = 0.5 * double(high.x - low.x) * width, up = 0.5 * double(high.y - low.y) * height;
    if (across < 1 && up < 1)
        throw std::invalid_argument("--camera: expected DIST 0 (frame the cube) or one at which it covers a pixel, found DIST " +
                                    number_text(view.distance) + " (the cube covers under a pixel: " + number_text(across) +
                                    " x " + number_text(up) + ")");
}

/// The timed frames' median ray-cast time, ms.
double ray_cast_ms(FrameRuns& runs) { return median(runs.stages["ray_cast"].wall_ms); }

/// Samples the last frame took per second of the median ray-cast time.
double samples_per_second(FrameRuns& runs) {
    const double ms = ray_cast_ms(runs);
    return ms > 0 ? double(runs.last.samples) / (ms * 1e-3) : 0;
}

/// stats.json of a volume run: input, configuration, stage medians, sample counts, machine.
nlohmann::json volume_stats(const VolumeOptions& o, const volume::TransferFunctionSettings& tf, const volume::VolumeCube& cube,
                            const volume::QuantisedVolume& levels, const volume::VolumeScene& scene, FrameRuns& runs,
                            double load_ms, double prepare_ms) {
    const unsigned threads = o.threads > 0 ? o.threads : std::max(1u, std::thread::hardware_concurrency());
    nlohmann::json stats;
    stats["command"] = "volume";
    stats["input"] = input_json(cube, levels);
    stats["configuration"] = configuration_json(o, tf, volume::make_view(cube.dims, o.settings), threads);
    stats["load_ms"] = load_ms;
    stats["prepare_ms"] = prepare_ms;
    bool all_valid = true;
    for (const auto& [name, series] : runs.stages) {
        stats["stages_ms"][name] = median(series.wall_ms);
        stats["stages_ms_all"][name] = series.wall_ms;
        const bool valid = o.caster == "gpu" && series.gl_query_valid;
        stats["gl_query_ms"][name] = median(series.gl_query_ms);
        stats["gl_query_valid_by_stage"][name] = valid;
        all_valid = all_valid && valid;
    }
    stats["stages_ms"]["total"] = median(runs.total_ms);
    stats["gl_query_valid"] = all_valid;
    stats["samples"] = runs.last.samples;
    stats["rays"] = runs.last.rays;
    stats["samples_per_ray"] = runs.last.rays ? double(runs.last.samples) / double(runs.last.rays) : 0.0;
    stats["samples_per_second"] = samples_per_second(runs);
    stats["occupied_block_fraction"] = scene.occupied_fraction();
    stats.update(run_context_json(runs.gl_device));
    return stats;
}

int run_volume(VolumeOptions& o) {
    volume::TransferFunctionSettings tf;
    apply_options(o, tf);
    refuse_overwrites({{"the cube", o.cube}}, {{"--out", o.out}, {"--stats", o.stats}});

    Clock::time_point start = Clock::now();
    const volume::VolumeCube cube = volume::load_segy(o.cube, o.read);
    const double load_ms = elapsed_ms(start);
    const volume::ViewGeometry view = volume::make_view(cube.dims, o.settings);
    refuse_eye_inside(view);
    refuse_cube_under_a_pixel(view, o.settings.width, o.settings.height);
    start = Clock::now();
    const volume::QuantisedVolume levels = volume::quantise(cube);
    refuse_blank_cube(cube, levels);
    if (!cube.missing_traces.empty())
        std::cerr << "cutaway: " << cube.source << ": irregular survey, " << cube.missing_traces.size()
                  << " missing traces filled with " << cube.null_value << '\n';
    if (o.window == "auto") tf.window = volume::percentile_window(levels);
    if (o.layer.empty()) tf.layer = volume::fitted_layer(tf.window);
    const volume::VolumeScene scene =
        volume::make_scene(levels, volume::build_transfer_table(tf), o.settings.block_size, tf.window);
    // The cube is framed between the colour bar it will carry and its time axis's values.
    volume::reserve_annotation_room(o.settings, scene);
    const double prepare_ms = elapsed_ms(start);

    FrameRuns runs = o.caster == "gpu" ? run_gpu(scene, o) : run_cpu(scene, o);
    // Committed together with the stats: a failed --stats leaves no image behind.
    io::OutputBatch outputs;
    outputs.write(o.out, gl::encode_png(runs.last.image, o.out));
    if (!o.stats.empty())
        outputs.write(o.stats, volume_stats(o, tf, cube, levels, scene, runs, load_ms, prepare_ms).dump(2) + '\n');
    outputs.commit();
    std::cout << o.out << ": " << o.caster << " caster, " << volume::transfer_function_name(tf.kind) << ", "
              << cube.dims.inlines << "x" << cube.dims.crosslines << "x" << cube.dims.samples << ", ray cast "
              << ray_cast_ms(runs) << " ms (median of " << o.repeat << "), " << runs.last.samples << " samples, "
              << samples_per_second(runs) / 1e6 << " M samples/s\n";
    return 0;
}

}  // namespace

CommandAction add_volume_command(CLI::App& app) {
    auto o = std::make_shared<VolumeOptions>();
    CLI::App* cmd = app.add_subcommand("volume", "Ray cast a seismic SEG-Y cube (Duan & Li) into a PNG, headless");
    cmd->add_option("cube", o->cube, "Post-stack SEG-Y cube")->required()->check(utf8_text());
    cmd->add_option("--out", o->out, "Output PNG")->required()->check(writable_output());
    cmd->add_option("--stats", o->stats, "Write times, sample counts and the configuration as JSON")
        ->check(writable_output());
    cmd->add_option("--tf", o->tf, "Transfer function: grey, pseudo or layer")->check(one_of({"grey", "pseudo", "layer"}));
    cmd->add_option("--window", o->window, "Levels the transfer function spans: auto (2-98 percentile) or full")
        ->check(one_of({"auto", "full"}));
    cmd->add_option("--colour-scale", o->colour_scale, "pseudo/layer colours: perceptual (viridis) or rainbow (the paper's)")
        ->check(one_of({"perceptual", "rainbow"}));
    cmd->add_option("--opacity", o->opacity, "grey/pseudo: opacity of the top level per voxel step (0..1)")
        ->check(finite_in(0, 1));
    CLI::Option* layer =
        cmd->add_option("--layer", o->layer,
                        "Layer highlight K R ALPHA_V F_V (levels; default: 1, half the window, 1, the window's top)")
            ->expected(4);
    layer->check(finite_in(0, 255, "", "K").application_index(0));
    layer->check(finite_above(0, 255, "levels", "R").application_index(1));
    layer->check(finite_in(0, 1, "", "ALPHA_V").application_index(2));
    layer->check(finite_in(0, 255, "levels", "F_V").application_index(3));
    // DIST in voxels: 1e6 is far beyond framing any cube the memory limit admits.
    check_orbit_values(
        *cmd->add_option("--camera", o->camera, "Azimuth, elevation (degrees), distance (voxels, 0 frames the cube)")
             ->expected(3),
        1e6);
    cmd->add_option("--size", o->size, "Image width and height (pixels)")->expected(2)->check(finite_in(16, 8192, "pixels"));
    cmd->add_option("--text-height", o->settings.text_height_px,
                    "capitals of the colour bar's and axes' text at least this tall, pixels (default: 2% of the image "
                    "height); 7 pt at a printed width W mm is 2.47 / W of the image width")
        ->check(finite_in(0, 200, "pixels"));
    cmd->add_option("--caster", o->caster, "gpu (fragment shader) or cpu (reference, std::thread)")
        ->check(one_of({"gpu", "cpu"}));
    // More threads than this only adds scheduling (100000 ran out of process resources).
    cmd->add_option("--threads", o->threads, "CPU caster threads (0: all cores)")->check(finite_in(0, 256));
    cmd->add_option("--step", o->settings.step, "Sample distance along rays (voxels)")->check(finite_above(0.01, 16, "voxels"));
    // A time sample drawn 1000 voxels long already stretches any cube past the frame.
    cmd->add_option("--time-scale", o->settings.time_scale, "Display length of a time sample (0: automatic)")
        ->check(finite_in(0, 1000));
    cmd->add_option("--block-size", o->settings.block_size, "Empty-space block edge (voxels)")->check(finite_in(2, 64, "voxels"));
    cmd->add_option("--early-termination-alpha", o->settings.early_termination_alpha, "Stop rays at this opacity")
        ->check(finite_above(0, 1));
    cmd->add_flag("--no-skip", o->no_skip, "No empty-space skipping");
    cmd->add_flag("--no-jitter", o->no_jitter, "Start every ray on the entry point");
    cmd->add_flag("--no-opacity-correction", o->no_opacity_correction, "Use table opacities whatever the step");
    cmd->add_flag("--no-early-termination", o->no_early_termination, "March every ray to its exit");
    cmd->add_flag("--no-colour-bar", o->no_colour_bar, "Leave the transfer-function bar out");
    // The same bounds as `render`'s: repetitions beyond 1000 add nothing to a median.
    cmd->add_option("--warmup", o->warmup, "Untimed frames first")->check(finite_in(0, 100));
    cmd->add_option("--repeat", o->repeat, "Timed frames (stats report medians)")->check(finite_in(1, 1000));
    cmd->add_option("--null-value", o->read.null_value, "Value for missing traces of irregular surveys")
        ->check(finite_in(-FLT_MAX, FLT_MAX));
    // A trace header is 240 bytes and a line number 4 of them.
    cmd->add_option("--inline-byte", o->read.inline_byte, "Trace header byte of the inline number")
        ->check(finite_in(1, 237));
    cmd->add_option("--crossline-byte", o->read.crossline_byte, "Trace header byte of the crossline number")
        ->check(finite_in(1, 237));
    add_memory_limit_option(*cmd, o->memory_limit_gb, "frames and cubes");
    return [o] { return run_volume(*o); };
}

}  // namespace cutaway::app

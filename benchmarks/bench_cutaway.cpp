// Cutaway frame times over the paper's camera path (SPEC.md section 3), one GL context per process.
//   BM_cutaway/pose/aperture/mean_filter/border/strategy/fraction_bp/draw/preset (preset varies slowest: one model
//     load each)
//     preset: index into --presets; draw: index into --draws (visible | all-faces, the paper's path);
//     fraction_bp: primary fraction in basis points (100 = 1%);
//     strategy: index into the cut-surface registry (filtered by --strategies); border: index into
//     the BorderMode name table (0 raycast, 1 threshold); mean_filter: k (0 = off); aperture: full opening angle in degrees (--apertures; -1 =
//     each pose's own along the path); pose: -1 = the whole path, else one pose (--per_pose).
//     Each iteration renders one pose of the path (warm-up passes first); the manual time is the
//     fenced wall time of the whole frame. Counters: median over the timed frames of the fenced
//     ms per stage and of its GL timer query beside it (`gpu_ms_<stage>`, stage_counters.h), baseline (median plain shaded frame of the same poses, same draw mode; not with
//     --baseline=0),
//     faces_secondary / faces_baseline (faces stage 2 and the plain frame drew, last pose),
//     gpu_query_valid (1 only if every GL query agreed), primary_pixels (the primaries' screen
//     footprint: visible primary pixels of each timed frame, median; read after the frame's fence,
//     outside its time), readback_bytes (the cut stage's read-back per frame, the largest seen).
//   BM_baseline/preset: the plain shaded frame over the same path (not with --baseline=0).
//   BM_cpu_path/aperture/strategy/fraction_bp/preset: for each chosen strategy computed on the GPU
//     that has a CPU reference (the cone-field transforms; --cpu_references narrows them), against
//     the CPU path it replaced, on the same inputs, interleaved per pose: seeds_ms (the GPU seed
//     pass alone), gpu_ms (the GPU strategy: seed pass + transform into the cut depth), cpu_path_ms
//     (the same seed pass, seed read-back, the CPU transform of cone_field/, the cut uploaded into
//     the cut depth), each fenced, medians; transform_speedup = (cpu_path - seeds) / (gpu - seeds),
//     stage_speedup = cpu_path / gpu. The iteration time is the CPU path's. Neither includes the
//     cut's normal/position resolve, the same for both (BM_cutaway's cut_surface includes it).
// Each benchmark checks its own output: at least one primary cell and visible primary pixels.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app_core/heap_policy.h"
#include "app_core/model_source.h"
#include "app_core/render_options.h"
#include "app_core/run_context.h"
#include "bench_cutaway_options.h"
#include "stage_counters.h"
#include "camera_path.h"
#include "cutaway/cut_surface/cone_field_strategy.h"
#include "cutaway/cut_surface/cut_seeds.h"
#include "cutaway/cut_surface/cut_strategy_choice.h"
#include "cutaway/cut_surface/cut_surface_registry.h"
#include "cutaway/frame_targets.h"
#include "cutaway/cutaway_renderer.h"
#include "cutaway/renderer_readback.h"
#include "gl/gl_context.h"
#include "gl/shader_library.h"
#include "metrics/median.h"

namespace {

using namespace cutaway;
using cutaway::metrics::median;

/// One loaded preset with its renderer; the bench keeps only the latest (1920x1080 targets are large).
struct Scene {
    std::unique_ptr<app::LoadedModel> model;
    app::PropertyChoice property;
    std::unique_ptr<pipeline::CutawayRenderer> renderer;
};

class SceneCache {
public:
    SceneCache(const gl::ShaderLibrary& shaders, int width, int height) : shaders_(shaders), width_(width), height_(height) {}

    Scene& scene(const std::string& preset) {
        if (preset != preset_) {
            scene_.renderer.reset();  // holds a reference to the old grid
            scene_.model = std::make_unique<app::LoadedModel>(app::load_model({"preset:" + preset}, memory_limit));
            const app::RenderOptions defaults;  // PORO
            scene_.property = app::choose_property(scene_.model->grid, defaults);
            scene_.renderer = std::make_unique<pipeline::CutawayRenderer>(shaders_, scene_.model->grid, 0.0, width_, height_);
            const app::PropertyChoice& p = scene_.property;
            scene_.renderer->set_colouring(p.values(), p.colour_bar_label());
            preset_ = preset;
        }
        return scene_;
    }

private:
    static constexpr std::size_t memory_limit = std::size_t(16) << 30;
    const gl::ShaderLibrary& shaders_;
    int width_, height_;
    std::string preset_;
    Scene scene_;
};

/// Selects the top `fraction` of the scene's property as primaries; returns their count.
std::size_t select_fraction(Scene& scene, double fraction) {
    app::RenderOptions options;
    options.primary_fraction = fraction;
    scene.renderer->select({scene.property.primary_range, app::choose_primary_range(scene.model->grid, scene.property, options)});
    return scene.renderer->status().primary_cells;
}

std::size_t visible_primary_pixels(const pipeline::CutawayRenderer& renderer) {
    const pipeline::IdImage ids = pipeline::FrameReadback(renderer).read_ids();
    return std::size_t(std::count_if(ids.flags.begin(), ids.flags.end(),
                                     [](std::uint32_t f) { return (f & pipeline::flag_primary) != 0; }));
}

std::vector<pipeline::Camera> path_cameras(const pipeline::CutawayRenderer& renderer,
                                           const std::vector<bench::PathPose>& path) {
    std::vector<pipeline::Camera> cameras;
    // Framed as `cutaway render` frames them: the colour bar (on in every benchmark) keeps its columns.
    const float bar_width = renderer.status(pipeline::FrameSettings{}).colour_bar_reserved_width;
    for (const bench::PathPose& pose : path)
        cameras.push_back(pipeline::make_orbit_camera(renderer.frame(), pose.orbit, renderer.status().width, renderer.status().height, bar_width));
    return cameras;
}

/// The poses one benchmark renders: the whole path, or only pose `index` (>= 0); with an aperture
/// (full opening angle, degrees; -1 = keep each pose's own).
std::vector<bench::PathPose> poses_for(const bench::CutawayBenchOptions& options, std::int64_t index,
                                       std::int64_t aperture_deg) {
    std::vector<bench::PathPose> path = bench::camera_path(options.poses);
    if (index >= 0) path = {path.at(std::size_t(index))};
    if (aperture_deg >= 0)
        for (bench::PathPose& pose : path) pose.aperture_deg = float(aperture_deg);
    return path;
}

struct BenchSetup {
    const gl::ShaderLibrary& shaders;
    const bench::CutawayBenchOptions& options;
    const std::vector<std::string>& strategies;
    SceneCache& cache;
};

/// The strategy in a benchmark's label: its name, or for "auto" the one it drew ("auto:frustum-sweep").
std::string drawn_strategy_label(const pipeline::CutawayRenderer& renderer, const pipeline::FrameSettings& settings) {
    const std::string drawn = renderer.status(settings).cut_strategy;
    return drawn == settings.strategy ? drawn : settings.strategy + ":" + drawn;
}

void bm_cutaway(benchmark::State& state, const BenchSetup& setup) {
    const bench::CutawayBenchOptions& options = setup.options;
    Scene& scene = setup.cache.scene(options.presets.at(std::size_t(state.range(7))));
    const std::size_t primaries = select_fraction(scene, double(state.range(5)) / 10000.0);
    if (primaries == 0) {
        state.SkipWithError("no primary cells selected");
        return;
    }
    pipeline::CutawayRenderer& renderer = *scene.renderer;
    pipeline::FrameSettings settings;
    settings.strategy = setup.strategies.at(std::size_t(state.range(4)));
    settings.border = pipeline::choices_of(pipeline::BorderMode{})[std::size_t(state.range(3))].value;
    settings.mean_filter = int(state.range(2));
    settings.line_width_px = 1;
    settings.ssao = options.ssao;
    settings.draw = *pipeline::find_choice(pipeline::choices_of(pipeline::DrawMode{}), options.draws.at(std::size_t(state.range(6))));
    // The paper's path keeps the paper's full-resolution SSAO; ours computes it for one pixel in four.
    settings.ssao_half_resolution = settings.draw == pipeline::DrawMode::visible;
    const std::vector<bench::PathPose> path = poses_for(options, state.range(0), state.range(1));
    const std::vector<pipeline::Camera> cameras = path_cameras(renderer, path);
    auto frame = [&](std::size_t k) {
        settings.aperture_h_deg = settings.aperture_v_deg = path[k].aperture_deg;
        return renderer.render(settings, cameras[k]);
    };

    for (int w = 0; w < options.warmup; ++w)
        for (std::size_t k = 0; k < path.size(); ++k) frame(k);
    bench::StageCounters stage_times;
    std::vector<double> primary_pixels;  // per timed frame
    std::size_t readback_bytes = 0;
    std::size_t k = 0;
    for (auto _ : state) {
        const pipeline::FrameTimes times = frame(k++ % path.size());
        state.SetIterationTime(times.total.wall_ms / 1000.0);
        readback_bytes = std::max(readback_bytes, renderer.status().cut_readback_bytes);
        primary_pixels.push_back(double(visible_primary_pixels(renderer)));
        bench::FrameStageTimes stages = bench::sum_by_stage(pipeline::stage_names, times.stages);
        stages.wall_ms["total"] = times.total.wall_ms;
        stages.gpu_ms["total"] = times.total.gl_query_ms;
        stage_times.add(stages);
    }
    if (primary_pixels.back() == 0) state.SkipWithError("no primary pixel visible in the last frame");
    const double faces_secondary = double(pipeline::FrameReadback(renderer).faces_drawn().secondary);

    stage_times.set_counters(state);
    state.counters["faces_secondary"] = faces_secondary;
    if (options.baseline) {
        std::vector<double> baseline;
        for (const pipeline::Camera& camera : cameras) baseline.push_back(renderer.render_baseline(camera, settings.draw).wall_ms);
        const double baseline_ms = median(baseline);
        state.counters["baseline"] = baseline_ms;
        state.counters["total_over_baseline"] = stage_times.median_wall_ms("total") / baseline_ms;
        state.counters["faces_baseline"] = double(pipeline::FrameReadback(renderer).faces_drawn().secondary);
    }
    state.counters["primary_cells"] = double(primaries);
    state.counters["primary_pixels"] = median(primary_pixels);
    state.counters["readback_bytes"] = double(readback_bytes);
    state.counters["cells"] = double(scene.model->grid.active_count());
    if (path.size() == 1 || state.range(1) >= 0) state.counters["aperture_deg"] = path.front().aperture_deg;
    state.SetLabel(options.presets.at(std::size_t(state.range(7))) + " " + pipeline::to_string(settings.draw) + " " +
                   drawn_strategy_label(renderer, settings) + " " +
                   pipeline::to_string(settings.border) + " mean_filter " + std::to_string(settings.mean_filter));
}

void bm_baseline(benchmark::State& state, const BenchSetup& setup) {
    Scene& scene = setup.cache.scene(setup.options.presets.at(std::size_t(state.range(0))));
    const std::vector<pipeline::Camera> cameras = path_cameras(*scene.renderer, poses_for(setup.options, -1, -1));
    for (int w = 0; w < setup.options.warmup; ++w)
        for (const pipeline::Camera& camera : cameras) scene.renderer->render_baseline(camera);
    std::size_t k = 0;
    for (auto _ : state) state.SetIterationTime(scene.renderer->render_baseline(cameras[k++ % cameras.size()]).wall_ms / 1000.0);
    state.counters["cells"] = double(scene.model->grid.active_count());
    state.SetLabel(setup.options.presets.at(std::size_t(state.range(0))));
}

/// Fenced wall time of `work`, milliseconds.
template <typename Work>
double fenced_ms(Work&& work) {
    glFinish();
    const auto started = std::chrono::steady_clock::now();
    work();
    glFinish();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
}

void bm_cpu_path(benchmark::State& state, const BenchSetup& setup) {
    const bench::CutawayBenchOptions& options = setup.options;
    Scene& scene = setup.cache.scene(options.presets.at(std::size_t(state.range(3))));
    if (select_fraction(scene, double(state.range(2)) / 10000.0) == 0) {
        state.SkipWithError("no primary cells selected");
        return;
    }
    const pipeline::CutSurfaceEntry entry = pipeline::find_cut_surface(setup.strategies.at(std::size_t(state.range(1))));
    const std::unique_ptr<pipeline::CutSurfaceStrategy> gpu = entry.make(setup.shaders);
    const std::unique_ptr<pipeline::CutSurfaceStrategy> cpu =
        pipeline::cone_field_entry(entry.name + " (CPU path)", "the path the GPU transform replaced", entry.cpu_reference)
            .make(setup.shaders);
    pipeline::CutSeedPass seed_pass(setup.shaders);
    const pipeline::CutTargets targets(options.width, options.height);
    const gl::VertexArray no_vertices;  // the passes draw without vertex buffers
    pipeline::FrameSettings settings;
    settings.strategy = entry.name;
    const std::vector<bench::PathPose> path = poses_for(options, -1, state.range(0));
    const std::vector<pipeline::Camera> cameras = path_cameras(*scene.renderer, path);
    // One sample per pose: the seed pass alone, the GPU strategy, the CPU path, interleaved.
    auto sample = [&](std::size_t k, std::map<std::string, std::vector<double>>& times) {
        settings.aperture_h_deg = settings.aperture_v_deg = path[k].aperture_deg;
        const pipeline::CutSurfaceInputs inputs = pipeline::RendererProbe(*scene.renderer).cut_inputs(settings, cameras[k]);
        no_vertices.bind();
        times["seeds_ms"].push_back(fenced_ms([&] { seed_pass.render_on_gpu(inputs); }));
        times["gpu_ms"].push_back(fenced_ms([&] { gpu->render(inputs, targets); }));
        times["cpu_path_ms"].push_back(fenced_ms([&] { cpu->render(inputs, targets); }));
        return times["cpu_path_ms"].back();
    };
    std::map<std::string, std::vector<double>> times;
    for (int w = 0; w < options.warmup; ++w)
        for (std::size_t k = 0; k < path.size(); ++k) sample(k, times);
    times.clear();
    std::size_t k = 0;
    for (auto _ : state) state.SetIterationTime(sample(k++ % path.size(), times) / 1000.0);
    for (const auto& [name, values] : times) state.counters[name] = median(values);
    const double seeds = median(times["seeds_ms"]), gpu_ms = median(times["gpu_ms"]), cpu_ms = median(times["cpu_path_ms"]);
    state.counters["stage_speedup"] = cpu_ms / gpu_ms;
    state.counters["transform_speedup"] = (cpu_ms - seeds) / std::max(gpu_ms - seeds, 1e-3);
    state.counters["readback_bytes_cpu_path"] = double(cpu->readback_bytes());
    state.SetLabel(options.presets.at(std::size_t(state.range(3))) + " " + entry.name + " GPU vs its CPU path");
}

std::vector<std::string> chosen_strategies(const std::vector<std::string>& requested) {
    std::vector<std::string> names;
    for (const std::string& name : requested) {
        if (name == "all")
            for (const pipeline::CutSurfaceEntry& entry : pipeline::cut_surface_strategies()) names.push_back(entry.name);
        else if (name == pipeline::auto_cut_strategy)
            names.push_back(name);  // the default: picks a registry strategy per frame
        else
            names.push_back(pipeline::find_cut_surface(name).name);  // throws for unknown names
    }
    return names;
}

template <class T>
std::vector<std::int64_t> indices(const std::vector<T>& items) {
    std::vector<std::int64_t> out(items.size());
    for (std::size_t i = 0; i < items.size(); ++i) out[i] = std::int64_t(i);
    return out;
}

bool wants_cpu_reference(const std::vector<std::string>& requested, const std::string& name) {
    return std::any_of(requested.begin(), requested.end(), [&](const std::string& r) { return r == "all" || r == name; });
}

void register_benchmarks(const BenchSetup& setup) {
    const bench::CutawayBenchOptions& o = setup.options;
    std::vector<std::int64_t> fractions_bp, borders, mean_filters(o.mean_filters.begin(), o.mean_filters.end());
    for (double f : o.fractions) fractions_bp.push_back(std::llround(f * 10000.0));
    const std::vector<std::string> border_names = pipeline::choice_names<pipeline::BorderMode>();
    for (const std::string& b : o.borders)
        borders.push_back(std::find(border_names.begin(), border_names.end(), b) - border_names.begin());
    std::vector<std::int64_t> poses{-1}, apertures(o.apertures.begin(), o.apertures.end());
    if (o.per_pose) poses = indices(bench::camera_path(o.poses));
    if (apertures.empty()) apertures = {-1};
    const std::int64_t iterations = std::int64_t(o.repeat) * (o.per_pose ? 1 : o.poses);
    benchmark::RegisterBenchmark("BM_cutaway", [&setup](benchmark::State& s) { bm_cutaway(s, setup); })
        ->ArgNames({"pose", "aperture", "mean_filter", "border", "strategy", "fraction_bp", "draw", "preset"})  // first varies fastest
        ->ArgsProduct({poses, apertures, mean_filters, borders, indices(setup.strategies), fractions_bp, indices(o.draws),
                       indices(o.presets)})
        ->Iterations(iterations)->UseManualTime()->Unit(benchmark::kMillisecond);
    std::vector<std::int64_t> with_reference;  // GPU strategies with a CPU reference
    for (std::size_t i = 0; i < setup.strategies.size(); ++i) {
        if (setup.strategies[i] == pipeline::auto_cut_strategy) continue;  // not a method of its own
        const pipeline::CutSurfaceEntry entry = pipeline::find_cut_surface(setup.strategies[i]);
        if (entry.device == "gpu" && entry.cpu_reference && wants_cpu_reference(o.cpu_references, entry.name))
            with_reference.push_back(std::int64_t(i));
    }
    if (!with_reference.empty())
        benchmark::RegisterBenchmark("BM_cpu_path", [&setup](benchmark::State& s) { bm_cpu_path(s, setup); })
            ->ArgNames({"aperture", "strategy", "fraction_bp", "preset"})
            ->ArgsProduct({apertures, with_reference, fractions_bp, indices(o.presets)})
            ->Iterations(std::int64_t(o.repeat) * o.poses)->UseManualTime()->Unit(benchmark::kMillisecond);
    if (!o.baseline) return;
    benchmark::RegisterBenchmark("BM_baseline", [&setup](benchmark::State& s) { bm_baseline(s, setup); })
        ->ArgNames({"preset"})->ArgsProduct({indices(o.presets)})
        ->Iterations(std::int64_t(o.repeat) * o.poses)->UseManualTime()->Unit(benchmark::kMillisecond);
}

void add_context(const bench::CutawayBenchOptions& o, const std::vector<std::string>& strategies, const gl::GlContext& context) {
    auto join = [](const std::vector<std::string>& items) {
        std::string text;
        for (const std::string& item : items) text += (text.empty() ? "" : ",") + item;
        return text;
    };
    benchmark::AddCustomContext("gl_renderer", gl::gl_renderer());
    benchmark::AddCustomContext("gl_version", gl::gl_version());
    benchmark::AddCustomContext("gl_platform", context.platform());
    benchmark::AddCustomContext("LP_NUM_THREADS", run_context::lp_num_threads());
    benchmark::AddCustomContext("heap_trim_threshold_bytes", app::heap_trim_threshold_json().dump());  // as stats.json
    benchmark::AddCustomContext("git_revision", run_context::git_revision());
    benchmark::AddCustomContext("uname", run_context::uname_text());
    benchmark::AddCustomContext("cutaway_build_type", CUTAWAY_BUILD_TYPE);
    benchmark::AddCustomContext("resolution", std::to_string(o.width) + "x" + std::to_string(o.height));
    benchmark::AddCustomContext("presets", join(o.presets));
    benchmark::AddCustomContext("strategies", join(strategies));
    benchmark::AddCustomContext("draws", join(o.draws));
    std::vector<std::string> apertures;
    for (const int a : o.apertures) apertures.push_back(std::to_string(a));
    benchmark::AddCustomContext("apertures_deg", apertures.empty() ? "camera path" : join(apertures));
    benchmark::AddCustomContext("statistic", "counters: median over the timed frames (poses x repeat)");
    std::string path;
    for (const bench::PathPose& p : bench::camera_path(o.poses))
        path += (path.empty() ? "" : "; ") + std::to_string(int(p.orbit.azimuth_deg)) + "/" +
                std::to_string(int(p.orbit.elevation_deg)) + "/" + std::to_string(int(p.aperture_deg));
    benchmark::AddCustomContext("camera_path_az_el_aperture_deg", path);
    benchmark::AddCustomContext("warmup_passes", std::to_string(o.warmup));
    benchmark::AddCustomContext("timed_passes", std::to_string(o.repeat));
    benchmark::AddCustomContext("frame_settings", std::string("line width 1 px, SSAO ") + (o.ssao ? "on" : "off") +
                                                      ", border width 1 px, distance framing the model");
    benchmark::AddCustomContext("baseline_frames", o.baseline ? "timed" : "skipped (--baseline=0)");
}

}  // namespace

int main(int argc, char** argv) {
    app::keep_freed_heap_memory();  // as `cutaway` (app_core/heap_policy.h)
    bench::CutawayBenchOptions options;
    CLI::App flags{"Cutaway frame times over the paper's camera path (Google Benchmark)", "bench_cutaway"};
    bench::add_cutaway_bench_flags(flags, options);
    if (const std::optional<int> exit_code = bench::parse_flags(flags, argc, argv)) return *exit_code;
    try {
        const std::vector<std::string> strategies = chosen_strategies(options.strategies);
        const std::unique_ptr<gl::GlContext> context = gl::create_context(gl::ContextOptions{});
        const gl::ShaderLibrary shaders(gl::ShaderLibrary::default_root());
        SceneCache cache(shaders, options.width, options.height);
        const BenchSetup setup{shaders, options, strategies, cache};
        add_context(options, strategies, *context);
        register_benchmarks(setup);
        benchmark::Initialize(&argc, argv);
        if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
        benchmark::RunSpecifiedBenchmarks();
        benchmark::Shutdown();
    } catch (const std::exception& error) {
        std::cerr << "bench_cutaway: " << error.what() << "\n";
        return 1;
    }
    return 0;
}

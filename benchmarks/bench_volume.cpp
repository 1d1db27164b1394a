// Seismic volume ray casting (issue 7): GPU and CPU casters, naive and with empty-space skipping,
// on a synthetic cube. Times are fenced wall clock (UseManualTime): the GPU's "ray_cast" stage of
// gl::StageTimer, the whole cast for the CPU. Counters: samples per frame, samples per second, the
// GPU caster's stages fenced and by GL timer query (`exit_points`, `gpu_ms_exit_points`, ...,
// `gpu_query_valid`: stage_counters.h), and the run's own checks (PSNR against the naive image /
// the GPU image, naive/skipping sample ratio).
//
//   bench_volume [--volume_dims=101x101x250] [--volume_size=256] [--cpu_threads=0] [benchmark flags]
#include <benchmark/benchmark.h>

#include <chrono>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include <CLI/CLI.hpp>

#include "app_core/option_checks.h"
#include "app_core/run_context.h"
#include "bench_cli.h"
#include "generators/seismic_model.h"
#include "gl/gl_context.h"
#include "gl/shader_library.h"
#include "stage_counters.h"
#include "volume/cpu_ray_caster.h"
#include "volume/gpu_ray_caster.h"
#include "volume/image_compare.h"

namespace {

using namespace cutaway;
using volume::CastResult;
using volume::RayCastSettings;
using volume::TransferFunctionKind;

struct BenchOptions {
    int inlines = 101, crosslines = 101, samples = 250;
    int image_size = 256;
    unsigned cpu_threads = 0;
};

/// Registers the flags above on `flags`, bound to `options`.
void add_volume_bench_flags(CLI::App& flags, BenchOptions& options) {
    bench::add_dims_option(flags, "--volume_dims", {&options.inlines, &options.crosslines, &options.samples}, 2, 4096,
                           "INLINESxCROSSLINESxSAMPLES", "samples", "synthetic cube's dimensions");
    flags.add_option("--volume_size", options.image_size, "image width = height, pixels")->check(app::finite_in(16, 8192, "pixels"));
    flags.add_option("--cpu_threads", options.cpu_threads, "CPU caster threads (0: one per hardware thread)")
        ->check(app::finite_in(0, 1024));
}

/// One transfer function's scene with the naive GPU frame every check compares against.
struct TransferCase {
    volume::VolumeScene scene;
    std::unique_ptr<volume::GpuRayCaster> gpu;
    CastResult naive_gpu;
};

/// Everything the benchmarks share: context, cube, scenes. Built once in main.
struct BenchState {
    BenchOptions options;
    std::unique_ptr<gl::GlContext> context;
    std::unique_ptr<gl::ShaderLibrary> shaders;
    volume::QuantisedVolume volume;
    std::map<TransferFunctionKind, TransferCase> cases;

    RayCastSettings settings(bool skipping) const {
        RayCastSettings s;
        s.width = s.height = options.image_size;
        s.empty_space_skipping = skipping;
        return s;
    }
};

volume::QuantisedVolume synthetic_volume(const BenchOptions& options) {
    generators::SeismicParameters p;
    p.inlines = options.inlines;
    p.crosslines = options.crosslines;
    p.samples = options.samples;
    const generators::SeismicVolume seismic = generators::generate_seismic(p);
    volume::VolumeCube cube;
    cube.dims = {p.inlines, p.crosslines, p.samples};
    cube.samples = seismic.amplitudes;
    return volume::quantise(cube);
}

void build_cases(BenchState& state) {
    for (TransferFunctionKind kind : {TransferFunctionKind::grey, TransferFunctionKind::layer}) {
        volume::TransferFunctionSettings tf;
        tf.kind = kind;
        TransferCase& c = state.cases[kind];
        c.scene = volume::make_scene(state.volume, volume::build_transfer_table(tf), RayCastSettings{}.block_size);
        c.gpu = std::make_unique<volume::GpuRayCaster>(*state.shaders, c.scene);
        gl::StageTimer timer;
        c.naive_gpu = c.gpu->render(state.settings(false), timer);
    }
}

/// Samples per second and the frame's samples; checks against the naive GPU image.
void report(benchmark::State& bench, const CastResult& frame, const CastResult& naive, double seconds, double frames) {
    bench.counters["samples"] = double(frame.samples);
    bench.counters["samples_per_second"] = seconds > 0 ? double(frame.samples) * frames / seconds : 0;
    const double psnr = volume::psnr_db(frame.image, naive.image);
    bench.counters["psnr_vs_naive_gpu_db"] = std::min(psnr, 999.0);
    bench.counters["naive_over_samples"] = double(naive.samples) / double(std::max<std::uint64_t>(frame.samples, 1));
    if (psnr < 40) bench.SkipWithError(("image differs from the naive GPU image: PSNR " + std::to_string(psnr) + " dB").c_str());
}

/// The GPU caster's timed stages (gpu_ray_caster.h) the counters report.
constexpr const char* gpu_stages[] = {"exit_points", "ray_cast", "readback"};

void gpu_cast(benchmark::State& bench, BenchState& state, TransferFunctionKind kind, bool skipping) {
    TransferCase& c = state.cases.at(kind);
    const RayCastSettings settings = state.settings(skipping);
    CastResult frame;
    gl::StageTimer warmup;
    c.gpu->render(settings, warmup);
    bench::StageCounters stages;
    double seconds = 0, frames = 0;
    for (auto _ : bench) {
        gl::StageTimer timer;
        frame = c.gpu->render(settings, timer);
        const double ms = timer.wall_ms("ray_cast");
        stages.add(bench::sum_by_stage(gpu_stages, timer.stages()));
        bench.SetIterationTime(ms * 1e-3);
        seconds += ms * 1e-3;
        ++frames;
    }
    stages.set_counters(bench);
    report(bench, frame, c.naive_gpu, seconds, frames);
}

void cpu_cast(benchmark::State& bench, BenchState& state, TransferFunctionKind kind, bool skipping) {
    TransferCase& c = state.cases.at(kind);
    const RayCastSettings settings = state.settings(skipping);
    CastResult frame = volume::cast_rays_cpu(c.scene, settings, state.options.cpu_threads);  // warm-up
    double seconds = 0, frames = 0;
    for (auto _ : bench) {
        const auto start = std::chrono::steady_clock::now();
        frame = volume::cast_rays_cpu(c.scene, settings, state.options.cpu_threads);
        const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        bench.SetIterationTime(s);
        seconds += s;
        ++frames;
    }
    report(bench, frame, c.naive_gpu, seconds, frames);
}

}  // namespace

int main(int argc, char** argv) {
    auto state = std::make_shared<BenchState>();
    CLI::App flags{"Seismic ray casting: GPU and CPU casters, naive and with empty-space skipping (Google Benchmark)",
                   "bench_volume"};
    add_volume_bench_flags(flags, state->options);
    if (const std::optional<int> exit_code = bench::parse_flags(flags, argc, argv)) return *exit_code;
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;

    state->context = gl::create_context(gl::ContextOptions{});
    state->shaders = std::make_unique<gl::ShaderLibrary>(gl::ShaderLibrary::default_root());
    state->volume = synthetic_volume(state->options);
    build_cases(*state);

    const BenchOptions& o = state->options;
    benchmark::AddCustomContext("gl_renderer", gl::gl_renderer());
    benchmark::AddCustomContext("LP_NUM_THREADS", run_context::lp_num_threads());
    benchmark::AddCustomContext("git_revision", run_context::git_revision());
    benchmark::AddCustomContext("volume_dims", std::to_string(o.inlines) + "x" + std::to_string(o.crosslines) + "x" +
                                                   std::to_string(o.samples));
    benchmark::AddCustomContext("image_size", std::to_string(o.image_size) + "x" + std::to_string(o.image_size));
    benchmark::AddCustomContext("cpu_threads", std::to_string(o.cpu_threads > 0 ? o.cpu_threads : std::thread::hardware_concurrency()));

    for (TransferFunctionKind kind : {TransferFunctionKind::grey, TransferFunctionKind::layer})
        for (bool skipping : {false, true}) {
            const std::string suffix = std::string("/") + volume::transfer_function_name(kind) + (skipping ? "/skipping" : "/naive");
            benchmark::RegisterBenchmark(("gpu" + suffix).c_str(), [=](benchmark::State& b) { gpu_cast(b, *state, kind, skipping); })
                ->UseManualTime()
                ->Unit(benchmark::kMillisecond);
            benchmark::RegisterBenchmark(("cpu" + suffix).c_str(), [=](benchmark::State& b) { cpu_cast(b, *state, kind, skipping); })
                ->UseManualTime()
                ->Unit(benchmark::kMillisecond)
                ->Iterations(5);
        }
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}

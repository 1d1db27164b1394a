// bench_distributed: one distributed cutaway frame across the ranks of `mpirun -np N` (issue 17),
// per preset, with the main job's settings (1% PORO primaries, default strategy, 9x9 mean filter,
// SSAO, ray-cast borders) at the default pose.
//
//   mpirun -np N build/bin/bench_distributed [--presets=petra,sapphire] [--size=WxH] [--frames=N]
//       [--warmup=N] [--slabs=i|j|k] [--benchmark_format=json ...]
//
// Every rank runs the same benchmarks with a fixed number of iterations (Google Benchmark's
// adaptive count could differ between ranks and leave one waiting in a collective). An
// iteration's time is the slowest rank's fenced frame (MPI max); counters are medians over the
// timed frames: each stage as the slowest rank ran it (fenced, and by GL timer query as
// `gpu_ms_<stage>` with `gpu_query_valid` over every rank: stage_counters.h), the allreduce and IceT times, bytes moved
// per frame, and the largest block. Only rank 0 reports. Each rank holds the whole preset while
// its renderer is built, then only its slab (RankRenderer): this measures frames, not loading.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app_core/heap_policy.h"
#include "app_core/model_source.h"
#include "app_core/option_checks.h"
#include "app_core/render_options.h"
#include "app_core/run_context.h"
#include "bench_cli.h"
#include "distributed/mpi_session.h"
#include "distributed/rank_blocks.h"
#include "distributed/rank_renderer.h"
#include "gl/gl_context.h"
#include "gl/shader_library.h"
#include "grid/face_classification.h"
#include "metrics/median.h"
#include "stage_counters.h"

namespace cutaway {
namespace {
using metrics::median;

constexpr std::size_t memory_limit = std::size_t(8) << 30;
/// The stages of a distributed frame the counters report (frame_plan.cpp names them).
constexpr const char* distributed_stages[] = {"cut_surface", "cut_combine", "culling", "secondary", "primary", "composite"};

struct DistributedBenchOptions {
    std::vector<std::string> presets{"zaphirus", "petra", "sapphire"};
    int width = 1920, height = 1080;
    int frames = 5, warmup = 1;
    distributed::SlabAxis slabs = distributed::SlabAxis::k;
};

/// Registers the flags above on `flags`, bound to `o`.
void add_distributed_bench_flags(CLI::App& flags, DistributedBenchOptions& o) {
    flags.add_option("--presets", o.presets, "models (preset:NAME), one benchmark each")
        ->delimiter(',')->check(app::one_of(bench::model_preset_names()));
    bench::add_dims_option(flags, "--size", {&o.width, &o.height}, 16, 32768, "WxH", "pixels", "image size");
    flags.add_option("--frames", o.frames, "timed frames")->check(app::finite_in(1, 1000));
    flags.add_option("--warmup", o.warmup, "untimed frames first")->check(app::finite_in(0, 100));
    flags.add_option_function<std::string>(
             "--slabs", [&o](const std::string& name) { o.slabs = distributed::slab_axis_from_name(name); },
             "the axis the model is split along into one slab per rank")
        ->check(app::one_of({"i", "j", "k"}))
        ->default_str(distributed::slab_axis_name(o.slabs));
}

/// Takes --benchmark_out* out of argv on ranks other than 0 (only rank 0 writes the file).
void drop_benchmark_out(int& argc, char** argv) {
    int kept = 1;
    for (int a = 1; a < argc; ++a)
        if (std::string(argv[a]).rfind("--benchmark_out", 0) != 0) argv[kept++] = argv[a];
    argc = kept;
}

struct BenchSetup {
    const DistributedBenchOptions& options;
    const distributed::MpiSession& mpi;
    const gl::ShaderLibrary& shaders;
};

void bm_distributed_frame(benchmark::State& state, const BenchSetup& setup, const std::string& preset) {
    const DistributedBenchOptions& o = setup.options;
    const distributed::MpiSession& mpi = setup.mpi;
    app::LoadedModel model = app::load_model({"preset:" + preset}, memory_limit, std::string("PORO"));
    app::RenderOptions render_options;
    app::PropertyChoice property = app::choose_property(model.grid, render_options);
    const std::optional<grid::IjkBox> box = app::choose_primary_range(model.grid, property, render_options);
    const pipeline::ModelFrame frame = pipeline::make_model_frame(model.grid, 0.0);
    const grid::IjkBox slab = distributed::split_into_slabs(model.grid, mpi.size(), o.slabs)[std::size_t(mpi.rank())];
    distributed::RankRenderer rank(setup.shaders, model.grid, frame, slab, grid::default_face_tolerance(model.grid),
                                   o.width, o.height);
    rank.set_colouring(property.values(), property.colour_bar_label());
    rank.select_range(property.primary_range, box);
    const pipeline::FrameSettings settings;  // the main job's: the defaults
    const pipeline::Camera camera = pipeline::make_orbit_camera(
        frame, pipeline::OrbitPose{}, o.width, o.height, rank.renderer().status(settings).colour_bar_reserved_width);

    for (int w = 0; w < o.warmup; ++w) rank.render(settings, camera);
    bench::StageCounters stages;                          // the slowest rank's, per timed frame
    std::map<std::string, std::vector<double>> exchanges;  // per timed frame, max (bytes: sum) over ranks
    for (auto _ : state) {
        const pipeline::FrameTimes times = rank.render(settings, camera);
        const double total_ms = mpi.max(times.total.wall_ms);
        state.SetIterationTime(total_ms / 1000.0);
        bench::FrameStageTimes frame = bench::sum_by_stage(distributed_stages, times.stages);
        for (auto& [name, ms] : frame.wall_ms) ms = mpi.max(ms);  // every rank asks for the same names
        for (auto& [name, ms] : frame.gpu_ms) ms = mpi.max(ms);
        frame.queries_valid = mpi.max(frame.queries_valid ? 0.0 : 1.0) == 0.0;
        frame.wall_ms["total"] = total_ms;
        frame.gpu_ms["total"] = mpi.max(times.total.gl_query_ms);
        stages.add(frame);
        const distributed::ExchangeCosts& exchange = rank.last_exchange();
        exchanges["allreduce_mpi_ms"].push_back(mpi.max(exchange.allreduce_ms));
        exchanges["icet_composite_ms"].push_back(mpi.max(exchange.composite_ms));
        exchanges["icet_bytes_sent"].push_back(double(mpi.sum(exchange.icet_bytes_sent)));
        exchanges["allreduce_message_bytes"].push_back(double(exchange.allreduce_bytes));
    }
    stages.set_counters(state);
    for (const auto& [name, values] : exchanges) state.counters[name] = median(values);
    state.counters["ranks"] = mpi.size();
    state.counters["active_cells"] = double(model.grid.active_count());
    state.counters["max_block_cells"] = mpi.max(double(rank.block().grid.cell_count()));
    state.counters["primary_cells"] = double(mpi.sum(rank.renderer().status().primary_cells));
    state.counters["max_peak_rss_bytes"] = mpi.max(double(run_context::proc_status_bytes("VmHWM")));
    state.SetLabel(preset + " " + std::to_string(mpi.size()) + " ranks, " + distributed::slab_axis_name(o.slabs) + " slabs, " +
                   settings.strategy);
}

/// Rank 0 reports; the others run the same benchmarks silently.
class SilentReporter final : public benchmark::BenchmarkReporter {
public:
    bool ReportContext(const Context&) override { return true; }
    void ReportRuns(const std::vector<Run>&) override {}
};

void add_context(const DistributedBenchOptions& o, const distributed::MpiSession& mpi, const gl::GlContext& context) {
    benchmark::AddCustomContext("gl_renderer", gl::gl_renderer());
    benchmark::AddCustomContext("gl_platform", context.platform());
    benchmark::AddCustomContext("LP_NUM_THREADS", run_context::lp_num_threads());
    benchmark::AddCustomContext("git_revision", run_context::git_revision());
    benchmark::AddCustomContext("uname", run_context::uname_text());
    benchmark::AddCustomContext("ranks", std::to_string(mpi.size()));
    benchmark::AddCustomContext("resolution", std::to_string(o.width) + "x" + std::to_string(o.height));
    benchmark::AddCustomContext("slab_axis", distributed::slab_axis_name(o.slabs));
    benchmark::AddCustomContext("timed_frames", std::to_string(o.frames));
    benchmark::AddCustomContext("warmup_frames", std::to_string(o.warmup));
    benchmark::AddCustomContext("statistic", "time: slowest rank's fenced frame; counters: medians over the timed "
                                             "frames of the slowest rank's value (bytes: summed over ranks)");
}

}  // namespace
}  // namespace cutaway

int main(int argc, char** argv) {
    using namespace cutaway;
    app::keep_freed_heap_memory();  // as `cutaway` (app_core/heap_policy.h)
    const distributed::MpiSession mpi;
    DistributedBenchOptions options;
    CLI::App flags{"One distributed cutaway frame across the ranks of mpirun (Google Benchmark)", "bench_distributed"};
    add_distributed_bench_flags(flags, options);
    // Every rank parses the same command line; rank 0 alone prints help or the refusal.
    const bench::Messages messages = mpi.root() ? bench::Messages::print : bench::Messages::silent;
    if (const std::optional<int> exit_code = bench::parse_flags(flags, argc, argv, bench::Arguments::with_google_benchmark, messages))
        return *exit_code;
    if (!mpi.root()) drop_benchmark_out(argc, argv);
    try {
        const std::unique_ptr<gl::GlContext> context = gl::create_context(gl::ContextOptions{});
        const gl::ShaderLibrary shaders(gl::ShaderLibrary::default_root());
        const BenchSetup setup{options, mpi, shaders};
        add_context(options, mpi, *context);
        for (const std::string& preset : options.presets)
            benchmark::RegisterBenchmark(("BM_distributed_frame/" + preset).c_str(),
                                         [&setup, preset](benchmark::State& s) { bm_distributed_frame(s, setup, preset); })
                ->Iterations(options.frames)->UseManualTime()->Unit(benchmark::kMillisecond);
        benchmark::Initialize(&argc, argv);
        if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;  // every rank has the same arguments
        SilentReporter silent;
        if (mpi.root()) benchmark::RunSpecifiedBenchmarks();
        else benchmark::RunSpecifiedBenchmarks(&silent);
        benchmark::Shutdown();
    } catch (const std::exception& error) {
        std::cerr << "bench_distributed: rank " << mpi.rank() << ": " << error.what() << "\n";
        mpi.abort(1);
    }
    return 0;
}

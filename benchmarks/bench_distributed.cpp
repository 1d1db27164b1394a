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
// timed frames: each stage as the slowest rank ran it, the allreduce and IceT times, bytes moved
// per frame, and the largest block. Only rank 0 reports. Each rank holds the whole preset while
// its renderer is built, then only its slab (RankRenderer): this measures frames, not loading.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "app/heap_policy.h"
#include "app/model_source.h"
#include "app/render_options.h"
#include "app/run_context.h"
#include "bench_cutaway_options.h"
#include "distributed/mpi_session.h"
#include "distributed/rank_blocks.h"
#include "distributed/rank_renderer.h"
#include "gl/gl_context.h"
#include "gl/shader_library.h"
#include "grid/face_classification.h"
#include "metrics/median.h"

namespace cutaway {
namespace {
using metrics::median;

constexpr std::size_t memory_limit = std::size_t(8) << 30;

struct DistributedBenchOptions {
    std::vector<std::string> presets{"zaphirus", "petra", "sapphire"};
    int width = 1920, height = 1080;
    int frames = 5, warmup = 1;
    distributed::SlabAxis slabs = distributed::SlabAxis::k;
};

const char* usage_text() {
    return "usage: mpirun -np N bench_distributed [--presets=a,b] [--size=WxH] [--frames=N] [--warmup=N] "
           "[--slabs=i|j|k] [--benchmark_* flags]\n";
}

/// Removes the flags above from argv, and on ranks other than 0 also --benchmark_out* (only rank 0
/// writes the file); throws std::invalid_argument on bad values.
DistributedBenchOptions take_options(int& argc, char** argv, bool root) {
    DistributedBenchOptions o;
    int kept = 1;
    for (int a = 1; a < argc; ++a) {
        const std::string arg = argv[a];
        const std::size_t eq = arg.find('=');
        const std::string flag = arg.substr(0, eq), value = eq == std::string::npos ? "" : arg.substr(eq + 1);
        if (flag == "--presets") o.presets = bench::split_list(value);
        else if (flag == "--frames") o.frames = bench::parse_list<int>(flag, value).at(0);
        else if (flag == "--warmup") o.warmup = bench::parse_list<int>(flag, value).at(0);
        else if (flag == "--slabs") o.slabs = distributed::slab_axis_from_name(value);
        else if (!root && flag.rfind("--benchmark_out", 0) == 0) continue;
        else if (flag == "--size") {
            const std::size_t x = value.find('x');
            if (x == std::string::npos) throw std::invalid_argument("--size: expected WxH, got '" + value + "'");
            o.width = bench::parse_list<int>(flag, value.substr(0, x)).at(0);
            o.height = bench::parse_list<int>(flag, value.substr(x + 1)).at(0);
        } else argv[kept++] = argv[a];
    }
    argc = kept;
    if (o.frames < 1 || o.warmup < 0) throw std::invalid_argument("--frames: at least 1, --warmup: at least 0");
    if (o.presets.empty()) throw std::invalid_argument("--presets: expected at least one preset");
    return o;
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
    std::map<std::string, std::vector<double>> slowest;  // per timed frame, max over ranks
    for (auto _ : state) {
        const pipeline::FrameTimes times = rank.render(settings, camera);
        const double total_ms = mpi.max(times.total.wall_ms);
        state.SetIterationTime(total_ms / 1000.0);
        slowest["total"].push_back(total_ms);
        std::map<std::string, double> stages;
        for (const gl::StageTime& stage : times.stages) stages[stage.stage] += stage.wall_ms;
        for (const char* name : {"cut_surface", "cut_combine", "culling", "secondary", "primary", "composite"})
            slowest[name].push_back(mpi.max(stages[name]));  // every rank asks for the same names
        const distributed::ExchangeCosts& exchange = rank.last_exchange();
        slowest["allreduce_mpi_ms"].push_back(mpi.max(exchange.allreduce_ms));
        slowest["icet_composite_ms"].push_back(mpi.max(exchange.composite_ms));
        slowest["icet_bytes_sent"].push_back(double(mpi.sum(exchange.icet_bytes_sent)));
        slowest["allreduce_message_bytes"].push_back(double(exchange.allreduce_bytes));
    }
    for (const auto& [name, values] : slowest) state.counters[name] = median(values);
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
    app::keep_freed_heap_memory();  // as `cutaway` (app/heap_policy.h)
    const distributed::MpiSession mpi;
    try {
        const DistributedBenchOptions options = take_options(argc, argv, mpi.root());
        const std::unique_ptr<gl::GlContext> context = gl::create_context(gl::ContextOptions{});
        const gl::ShaderLibrary shaders(gl::ShaderLibrary::default_root());
        const BenchSetup setup{options, mpi, shaders};
        add_context(options, mpi, *context);
        for (const std::string& preset : options.presets)
            benchmark::RegisterBenchmark(("BM_distributed_frame/" + preset).c_str(),
                                         [&setup, preset](benchmark::State& s) { bm_distributed_frame(s, setup, preset); })
                ->Iterations(options.frames)->UseManualTime()->Unit(benchmark::kMillisecond);
        benchmark::Initialize(&argc, argv);
        if (benchmark::ReportUnrecognizedArguments(argc, argv)) {
            if (mpi.root()) std::cerr << usage_text();
            return 1;
        }
        SilentReporter silent;
        if (mpi.root()) benchmark::RunSpecifiedBenchmarks();
        else benchmark::RunSpecifiedBenchmarks(&silent);
        benchmark::Shutdown();
    } catch (const std::exception& error) {
        std::cerr << "bench_distributed: rank " << mpi.rank() << ": " << error.what() << "\n" << usage_text();
        mpi.abort(1);
    }
    return 0;
}

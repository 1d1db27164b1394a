// A primary-range change (the viewer's range slider, a new time step's threshold): the GPU
// selection (CutawayRenderer::select_range: compute passes over the values already uploaded,
// 8 bytes read back) against the CPU path it replaces (grid::select_primaries, the CPU face
// lists, and their upload), in the same run.
//   BM_select/path/preset: path 0 = gpu, 1 = cpu; preset: index into --presets (default
//   petra,sapphire,scale-1m). Each iteration alternates between the top 1% and top 2% of the
//   preset's default property, fenced with glFinish. Counter: primary_cells (last selection).
#include <benchmark/benchmark.h>

#include <chrono>
#include <iostream>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app_core/model_source.h"
#include "app_core/option_checks.h"
#include "app_core/render_options.h"
#include "app_core/run_context.h"
#include "bench_cli.h"
#include "cutaway/cutaway_renderer.h"
#include "cutaway/grid_layout.h"
#include "gl/gl_context.h"
#include "gl/shader_library.h"
#include "grid/face_classification.h"

namespace {

using namespace cutaway;

/// The CPU path: flags, face lists and bits on the CPU, uploaded as new buffers.
std::size_t select_on_cpu(const grid::CornerPointGrid& grid, const app::PropertyChoice& property,
                          const pipeline::GridLayout& layout, const grid::PrimaryRange& range) {
    const std::vector<std::uint8_t> flags = grid::select_primaries(grid, property.values(), property.name, range);
    const pipeline::FaceLists lists = pipeline::build_face_lists(grid, layout, flags, false);
    const std::vector<std::uint32_t> bits = pipeline::primary_bits(layout, flags);
    const gl::Buffer primary = gl::Buffer::from(std::span<const std::uint32_t>(lists.primary));
    const gl::Buffer cells = gl::Buffer::from(std::span<const std::uint32_t>(lists.primary_cells));
    const gl::Buffer words = gl::Buffer::from(std::span<const std::uint32_t>(bits));
    glFinish();
    return lists.primary_cells.size();
}

void bm_select(benchmark::State& state, const std::vector<std::string>& presets, const gl::ShaderLibrary& shaders) {
    const bool gpu = state.range(0) == 0;
    const std::string& preset = presets.at(std::size_t(state.range(1)));
    const app::LoadedModel model = app::load_model({"preset:" + preset}, std::size_t(16) << 30);
    const grid::CornerPointGrid& grid = model.grid;
    const app::RenderOptions defaults;  // PORO
    const app::PropertyChoice property = app::choose_property(grid, defaults);
    pipeline::CutawayRenderer renderer(shaders, grid, 0.0, 64, 64);
    renderer.set_colouring(property.values(), property.colour_bar_label());
    pipeline::GridLayout layout;  // the CPU path's input
    if (!gpu)
        layout = pipeline::build_grid_layout(grid, grid::FaceClassification(grid, grid::default_face_tolerance(grid)),
                                             pipeline::make_model_frame(grid, 0.0));
    grid::PrimaryRange ranges[2];
    for (int i = 0; i < 2; ++i) ranges[i] = grid::range_for_fraction(grid, property.values(), property.name, 0.01 * (i + 1));
    std::size_t primaries = 0, iteration = 0;
    for (auto _ : state) {
        const grid::PrimaryRange& range = ranges[iteration++ % 2];
        const auto start = std::chrono::steady_clock::now();
        if (gpu) {
            renderer.select(range);
            glFinish();
            primaries = renderer.status().primary_cells;
        } else {
            primaries = select_on_cpu(grid, property, layout, range);
        }
        state.SetIterationTime(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    if (primaries == 0) state.SkipWithError("no primary cell selected");
    state.counters["primary_cells"] = double(primaries);
    state.counters["active_cells"] = double(grid.active_count());
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> presets{"petra", "sapphire", "scale-1m"};
    CLI::App flags{"A primary-range change: GPU selection against the CPU lists it replaced (Google Benchmark)",
                   "bench_selection"};
    flags.add_option("--presets", presets, "models (preset:NAME), one benchmark pair each")
        ->delimiter(',')->check(app::one_of(bench::model_preset_names()));
    if (const std::optional<int> exit_code = bench::parse_flags(flags, argc, argv)) return *exit_code;
    try {
        const std::unique_ptr<gl::GlContext> context = gl::create_context(gl::ContextOptions{});
        const gl::ShaderLibrary shaders(gl::ShaderLibrary::default_root());
        benchmark::AddCustomContext("gl_renderer", gl::gl_renderer());
        benchmark::AddCustomContext("LP_NUM_THREADS", run_context::lp_num_threads());
        benchmark::AddCustomContext("git_revision", run_context::git_revision());
        benchmark::AddCustomContext("paths", "0 = gpu (select_range), 1 = cpu (select_primaries + face lists + upload)");
        std::vector<std::int64_t> preset_indices;
        for (std::size_t i = 0; i < presets.size(); ++i) preset_indices.push_back(std::int64_t(i));
        benchmark::RegisterBenchmark("BM_select", [&](benchmark::State& s) { bm_select(s, presets, shaders); })
            ->ArgNames({"path", "preset"})
            ->ArgsProduct({{0, 1}, preset_indices})
            ->Iterations(10)->Repetitions(3)->ReportAggregatesOnly(true)->UseManualTime()->Unit(benchmark::kMillisecond);
        benchmark::Initialize(&argc, argv);
        if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
        benchmark::RunSpecifiedBenchmarks();
        benchmark::Shutdown();
    } catch (const std::exception& error) {
        std::cerr << "bench_selection: " << error.what() << "\n";
        return 1;
    }
    return 0;
}

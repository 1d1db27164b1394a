// Loading the Reek grid (40x64x14, 3.7 MB of GRDECL text) side by side, same process, same run:
//   BM_LoadReek_Cutaway        our load_grdecl({reek_sim_grid.grdecl})
//   BM_LoadReek_OPM            OPM: Parser::parseFile + EclipseGrid(deck, ACTNUM)
// plus two reference points that are not part of the ratio:
//   BM_LoadReekWithPoro_Cutaway  grid + reek_sim_poro.grdecl (what the viewer loads)
//   BM_OpmParserConstruction     Opm::Parser() with its built-in keyword set (paid once per
//                                process by an OPM user, so kept out of BM_LoadReek_OPM)
// After the run it prints "speed ratio OPM / cutaway" from the median (or only) real times and,
// when --benchmark_out=FILE.json is given, adds the same numbers to that file as
// "cutaway_summary".
//
// OPM 2022.10's EclipseGrid(const Deck&) ignores the ACTNUM of a deck without a GRID section
// (a bare GRDECL file), so the OPM side passes the deck's ACTNUM explicitly; both sides then
// build the same 35,838-active-cell grid.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "app_core/run_context.h"
#include "bench_cli.h"
#include "grid/grdecl_reader.h"

#ifdef CUTAWAY_HAVE_OPM
#include <opm/input/eclipse/Deck/Deck.hpp>
#include <opm/input/eclipse/Deck/DeckKeyword.hpp>
#include <opm/input/eclipse/EclipseState/Grid/EclipseGrid.hpp>
#include <opm/input/eclipse/Parser/ErrorGuard.hpp>
#include <opm/input/eclipse/Parser/InputErrorAction.hpp>
#include <opm/input/eclipse/Parser/ParseContext.hpp>
#include <opm/input/eclipse/Parser/Parser.hpp>
#endif

namespace {

namespace fs = std::filesystem;

const fs::path kReekDir = fs::path(CUTAWAY_SHARED_DATA) / "grdecl" / "reek";
const fs::path kReekGrid = kReekDir / "reek_sim_grid.grdecl";
const fs::path kReekPoro = kReekDir / "reek_sim_poro.grdecl";

constexpr const char* kOurs = "BM_LoadReek_Cutaway";
constexpr const char* kOpm = "BM_LoadReek_OPM";

void set_common_counters(benchmark::State& state, std::size_t cells, std::size_t active, std::uintmax_t bytes) {
    state.counters["cells"] = double(cells);
    state.counters["active_cells"] = double(active);
    state.SetBytesProcessed(std::int64_t(state.iterations()) * std::int64_t(bytes));
}

void BM_LoadReek_Cutaway(benchmark::State& state) {
    std::size_t cells = 0, active = 0;
    for (auto _ : state) {
        cutaway::grid::CornerPointGrid grid = cutaway::grid::load_grdecl({kReekGrid});
        cells = grid.cell_count();
        active = grid.active_count();
        benchmark::DoNotOptimize(grid);
    }
    set_common_counters(state, cells, active, fs::file_size(kReekGrid));
}
BENCHMARK(BM_LoadReek_Cutaway)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_LoadReekWithPoro_Cutaway(benchmark::State& state) {
    std::size_t cells = 0, active = 0;
    for (auto _ : state) {
        cutaway::grid::CornerPointGrid grid = cutaway::grid::load_grdecl({kReekGrid, kReekPoro});
        cells = grid.cell_count();
        active = grid.active_count();
        benchmark::DoNotOptimize(grid);
    }
    set_common_counters(state, cells, active, fs::file_size(kReekGrid) + fs::file_size(kReekPoro));
}
BENCHMARK(BM_LoadReekWithPoro_Cutaway)->Unit(benchmark::kMillisecond)->UseRealTime();

#ifdef CUTAWAY_HAVE_OPM
void BM_LoadReek_OPM(benchmark::State& state) {
    const Opm::Parser parser;  // built once, as an OPM application would (see BM_OpmParserConstruction)
    std::size_t cells = 0, active = 0;
    for (auto _ : state) {
        const Opm::ParseContext context;
        Opm::ErrorGuard errors;
        const Opm::Deck deck = parser.parseFile(kReekGrid.string(), context, errors);
        const std::vector<int>& actnum = deck["ACTNUM"].back().getIntData();
        const Opm::EclipseGrid grid(deck, actnum.data());
        cells = grid.getCartesianSize();
        active = grid.getNumActive();
        errors.clear();
        benchmark::DoNotOptimize(&grid);
    }
    set_common_counters(state, cells, active, fs::file_size(kReekGrid));
}
BENCHMARK(BM_LoadReek_OPM)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_OpmParserConstruction(benchmark::State& state) {
    for (auto _ : state) {
        Opm::Parser parser;
        benchmark::DoNotOptimize(&parser);
    }
}
BENCHMARK(BM_OpmParserConstruction)->Unit(benchmark::kMillisecond)->UseRealTime();
#endif

/// Console reporter that also remembers, per benchmark function, the median real time
/// (or the single run's when there are no repetitions), in milliseconds.
class RatioReporter : public benchmark::ConsoleReporter {
public:
    using ConsoleReporter::ConsoleReporter;

    void ReportRuns(const std::vector<Run>& runs) override {
        for (const Run& run : runs) {
            if (run.error_occurred) continue;
            const std::string& name = run.run_name.function_name;
            const double ms = run.GetAdjustedRealTime() * to_ms(run.time_unit);
            if (run.run_type == Run::RT_Aggregate && run.aggregate_name == "median")
                median_ms_[name] = ms;
            else if (run.run_type == Run::RT_Iteration)
                single_ms_[name] = ms;  // the last repetition; used only without aggregates
        }
        ConsoleReporter::ReportRuns(runs);
    }

    /// Median if there were repetitions, else the only run; negative if it did not run.
    double ms(const std::string& name) const {
        if (const auto it = median_ms_.find(name); it != median_ms_.end()) return it->second;
        if (const auto it = single_ms_.find(name); it != single_ms_.end()) return it->second;
        return -1.0;
    }
    bool has_median(const std::string& name) const { return median_ms_.count(name) != 0; }

private:
    static double to_ms(benchmark::TimeUnit unit) {
        switch (unit) {
            case benchmark::kNanosecond: return 1e-6;
            case benchmark::kMicrosecond: return 1e-3;
            case benchmark::kMillisecond: return 1.0;
            case benchmark::kSecond: return 1e3;
        }
        return 1.0;
    }
    std::map<std::string, double> median_ms_;
    std::map<std::string, double> single_ms_;
};

/// The value of --benchmark_out=FILE among the arguments (before benchmark::Initialize eats them).
std::string benchmark_out_path(int argc, char** argv) {
    const std::string flag = "--benchmark_out=";
    std::string path;
    for (int a = 1; a < argc; ++a) {
        const std::string arg = argv[a];
        if (arg.rfind(flag, 0) == 0) path = arg.substr(flag.size());
    }
    return path;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App flags{"Loading the Reek grid: our reader against OPM's (Google Benchmark; no flags of its own)",
                   "bench_grid_load"};
    if (const std::optional<int> exit_code = cutaway::bench::parse_flags(flags, argc, argv)) return *exit_code;
    const std::string out_path = benchmark_out_path(argc, argv);

    benchmark::AddCustomContext("git_revision", cutaway::run_context::git_revision());
    benchmark::AddCustomContext("uname", cutaway::run_context::uname_text());
    benchmark::AddCustomContext("cutaway_build_type", CUTAWAY_BUILD_TYPE);
    benchmark::AddCustomContext("cutaway_cxx_flags", CUTAWAY_CXX_FLAGS);
    benchmark::AddCustomContext("reek_grid_file", kReekGrid.string());
    if (const std::string lp = cutaway::run_context::env_or_empty("LP_NUM_THREADS"); !lp.empty())
        benchmark::AddCustomContext("LP_NUM_THREADS", lp);
    if (const std::string omp = cutaway::run_context::env_or_empty("OMP_NUM_THREADS"); !omp.empty())
        benchmark::AddCustomContext("OMP_NUM_THREADS", omp);
#ifdef CUTAWAY_HAVE_OPM
    benchmark::AddCustomContext("opm_common_version", CUTAWAY_OPM_VERSION);
#else
    benchmark::AddCustomContext("opm_common_version", "not built (CUTAWAY_OPM_REFERENCE=OFF)");
#endif

    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
    if (!fs::is_regular_file(kReekGrid)) {
        std::cerr << "bench_grid_load: missing " << kReekGrid << "\n";
        return 1;
    }

    RatioReporter reporter(::isatty(STDOUT_FILENO) ? benchmark::ConsoleReporter::OO_ColorTabular
                                                   : benchmark::ConsoleReporter::OO_Tabular);
    benchmark::RunSpecifiedBenchmarks(&reporter);
    benchmark::Shutdown();

    const double ours_ms = reporter.ms(kOurs);
    const double opm_ms = reporter.ms(kOpm);
    if (ours_ms <= 0 || opm_ms <= 0) return 0;  // filtered out, or OPM not built

    const double ratio = opm_ms / ours_ms;
    const char* statistic = reporter.has_median(kOurs) && reporter.has_median(kOpm) ? "median" : "single run";
    std::printf("\nspeed ratio OPM / cutaway (%s real time per load): %.2fx  (OPM %.2f ms, cutaway %.2f ms)\n",
                statistic, ratio, opm_ms, ours_ms);

    if (!out_path.empty()) {
        // Add the ratio to the JSON written by --benchmark_out (skipped for other formats).
        nlohmann::json doc;
        {
            std::ifstream in(out_path);
            doc = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
        }
        if (doc.is_object()) {
            doc["cutaway_summary"] = {
                {"statistic", statistic},
                {"cutaway_ms_per_load", ours_ms},
                {"opm_ms_per_load", opm_ms},
                {"opm_over_cutaway", ratio},
                {"with_poro_cutaway_ms_per_load", reporter.ms("BM_LoadReekWithPoro_Cutaway")},
                {"opm_parser_construction_ms", reporter.ms("BM_OpmParserConstruction")},
            };
            std::ofstream(out_path) << doc.dump(2) << "\n";
        }
    }
    return 0;
}

// Speed and peak memory of `cutaway generate` on the scale presets (generate + write GRDECL).
//
//   bench_generate [--preset scale-1m] [--repetitions N] [--warmup N] [--dir DIR] [--json OUT]
//
// One preset per process, so VmHWM (/proc/self/status) is that preset's peak resident memory.
// Each repetition generates the model and streams it to DIR/<preset>.grdecl; the first `warmup`
// runs are not timed. Then the benchmark checks its own output: the file has the bytes written,
// its header reports the grid's active count, and every repetition produced the same bytes
// (same size and FNV-1a hash). Targets (issue 3): 1M cells in at most 15 s, 10M cells in at
// most 180 s with at most 4 GiB peak.
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "app_core/option_checks.h"
#include "app_core/run_context.h"
#include "bench_cli.h"
#include "generators/generator.h"
#include "generators/presets.h"
#include "generators/write_progress.h"
#include "grid/grdecl_writer.h"
#include "metrics/median.h"

namespace {

namespace fs = std::filesystem;
using namespace cutaway;
using cutaway::metrics::median;

struct Options {
    std::string preset = "scale-1m";
    int repetitions = 3;
    int warmup = 1;
    fs::path dir = fs::temp_directory_path();
    fs::path json_out;
};

/// A limit from the issue: seconds per run and peak bytes, by preset.
struct Target {
    double max_seconds;
    double max_peak_bytes;
};

Target target_for(const std::string& preset) {
    if (preset == "scale-10m") return {180, 4.0 * (1ull << 30)};
    if (preset == "scale-1m") return {15, 4.0 * (1ull << 30)};
    return {15, 4.0 * (1ull << 30)};
}

/// Peak resident set (VmHWM) of this process, bytes.
std::size_t peak_resident_bytes() {
    std::ifstream status("/proc/self/status");
    for (std::string line; std::getline(status, line);)
        if (line.rfind("VmHWM:", 0) == 0) return std::stoull(line.substr(6)) * 1024;
    return 0;
}

std::uint64_t fnv1a(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::uint64_t hash = 0xcbf29ce484222325ull;
    std::vector<char> buffer(1 << 20);
    while (in.read(buffer.data(), std::streamsize(buffer.size())) || in.gcount() > 0) {
        for (std::streamsize n = 0; n < in.gcount(); ++n) hash = (hash ^ std::uint8_t(buffer[std::size_t(n)])) * 0x100000001b3ull;
    }
    return hash;
}

struct Run {
    double generate_s = 0;
    double write_s = 0;
    std::size_t bytes = 0;
    std::size_t active = 0;
};

Run run_once(const generators::GeneratorParameters& p, const fs::path& file) {
    using clock = std::chrono::steady_clock;
    const auto t0 = clock::now();
    generators::ProgressLog progress(&std::cerr);
    const generators::GeneratedModel model = generators::generate_model(p, progress);
    const auto t1 = clock::now();
    grid::GrdeclWriteOptions options;
    options.header_comments = generators::header_lines(p, model.report);
    Run run;
    {
        std::ofstream out_file(file, std::ios::binary);
        generators::WriteProgressBuf buffer(out_file.rdbuf(), &std::cerr);
        std::ostream out(&buffer);
        grid::write_grdecl(out, model.grid, options);
        out.flush();
        run.bytes = buffer.bytes_written();
        if (!out || !out_file.flush()) throw std::runtime_error(file.string() + ": write failed");
    }
    const auto t2 = clock::now();
    run.generate_s = std::chrono::duration<double>(t1 - t0).count();
    run.write_s = std::chrono::duration<double>(t2 - t1).count();
    run.active = model.grid.active_count();
    return run;
}

/// The "-- active_cells = N" header line of the written file.
std::size_t header_active_cells(const fs::path& file) {
    std::ifstream in(file);
    for (std::string line; std::getline(in, line) && line.rfind("--", 0) == 0;)
        if (line.rfind("-- active_cells = ", 0) == 0) return std::stoull(line.substr(18));
    return 0;
}

std::string utc_now() {
    const std::time_t now = std::time(nullptr);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
    return text;
}

/// Registers the flags above on `flags`, bound to `o`.
void add_generate_bench_flags(CLI::App& flags, Options& o) {
    flags.add_option("--preset", o.preset, "model preset to generate")->check(app::one_of(bench::model_preset_names()));
    flags.add_option("--repetitions", o.repetitions, "timed runs")->check(app::finite_in(1, 1000));
    flags.add_option("--warmup", o.warmup, "untimed runs first")->check(app::finite_in(0, 100));
    flags.add_option("--dir", o.dir, "folder the GRDECL file is written to (and removed from)");
    flags.add_option("--json", o.json_out, "also write the report here (its folders made)");
}

}  // namespace

int main(int argc, char** argv) try {
    Options options;
    CLI::App flags{"Speed and peak memory of generating a preset and writing its GRDECL", "bench_generate"};
    add_generate_bench_flags(flags, options);
    if (const std::optional<int> exit_code = bench::parse_flags(flags, argc, argv, bench::Arguments::all_ours))
        return *exit_code;
    const generators::GeneratorParameters p = generators::find_preset(options.preset);
    const fs::path file = options.dir / ("bench_generate_" + options.preset + ".grdecl");
    for (int w = 0; w < options.warmup; ++w) run_once(p, file);

    std::vector<Run> runs;
    std::vector<std::uint64_t> hashes;
    for (int r = 0; r < options.repetitions; ++r) {
        runs.push_back(run_once(p, file));
        hashes.push_back(fnv1a(file));
    }
    const std::size_t peak = peak_resident_bytes();

    // Check our own output.
    const std::size_t on_disk = fs::file_size(file);
    const std::size_t header_active = header_active_cells(file);
    bool identical = true;
    for (std::size_t r = 1; r < runs.size(); ++r) identical = identical && hashes[r] == hashes[0] && runs[r].bytes == runs[0].bytes;
    fs::remove(file);
    const bool output_ok = on_disk == runs.back().bytes && header_active == runs.back().active && identical;

    std::vector<double> generate_s, write_s, total_s;
    for (const Run& r : runs) {
        generate_s.push_back(r.generate_s);
        write_s.push_back(r.write_s);
        total_s.push_back(r.generate_s + r.write_s);
    }
    const Target target = target_for(options.preset);
    const double worst_total = *std::max_element(total_s.begin(), total_s.end());
    nlohmann::json j;
    j["benchmark"] = "bench_generate";
    j["preset"] = p.name;
    j["dims"] = {p.dims.nx, p.dims.ny, p.dims.nz};
    j["cells"] = p.dims.cell_count();
    j["active_cells"] = runs.back().active;
    j["parameters"] = generators::describe(p);
    j["warmup"] = options.warmup;
    j["repetitions"] = options.repetitions;
    j["generate_s"] = generate_s;
    j["write_s"] = write_s;
    j["total_s"] = total_s;
    j["median_total_s"] = median(total_s);
    j["max_total_s"] = worst_total;
    j["file_bytes"] = runs.back().bytes;
    j["peak_resident_bytes"] = peak;
    j["estimated_peak_bytes"] = generators::estimated_peak_bytes(p);
    j["checks"] = {{"file_size_matches", on_disk == runs.back().bytes},
                   {"header_active_cells_matches", header_active == runs.back().active},
                   {"repetitions_byte_identical", identical}};
    j["target"] = {{"max_seconds", target.max_seconds}, {"max_peak_bytes", target.max_peak_bytes}};
    j["meets_target"] = worst_total <= target.max_seconds && double(peak) <= target.max_peak_bytes;
    j["context"] = {{"uname", run_context::uname_text()},
                    {"nproc", std::thread::hardware_concurrency()},
                    {"git_revision", run_context::git_revision()},
                    {"date_utc", utc_now()},
                    {"build_type", CUTAWAY_BUILD_TYPE},
                    {"compiler", std::string("g++ ") + __VERSION__},
                    {"cxx_flags", CUTAWAY_CXX_FLAGS},
                    {"output_dir", options.dir.string()}};
    std::cout << j.dump(2) << '\n';
    if (!options.json_out.empty()) {
        fs::create_directories(options.json_out.parent_path());
        std::ofstream(options.json_out) << j.dump(2) << '\n';
    }
    return output_ok ? 0 : 1;
} catch (const std::exception& error) {
    std::cerr << "bench_generate: " << error.what() << '\n';
    return 2;
}

// Peak memory of loading a 10-million-cell box GRDECL with our reader.
//
//   bench_grid_memory [--nx 250 --ny 400 --nz 100] [--no-poro] [--dir DIR] [--keep] [--json OUT]
//       Driver: runs the two steps below as separate processes (fork + exec of this program),
//       so the writer's memory never shows in the measurement, then prints the load step's JSON.
//   bench_grid_memory --write FILE [--nx ...] [--no-poro]
//       Builds the box in memory (make_box_grid: vertical pillars, flat layers, all active, and
//       a PORO property unless --no-poro) and writes it with write_grdecl.
//   bench_grid_memory --load FILE [--json OUT]
//       Reads VmHWM/VmRSS from /proc/self/status, loads FILE with load_grdecl, reads them again,
//       and reports (as JSON on stdout, and in OUT if given):
//         peak bytes   = VmHWM after - VmHWM before (the process's high-water mark of the load)
//         geometry     = grid.geometry_bytes() (COORD + ZCORN + ACTNUM), properties likewise
//       each also per cell. Target: a loaded grid costs at most 64 bytes per cell plus its
//       properties, i.e. (peak - property bytes) / cells <= 64 and geometry / cells <= 64.
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "app_core/option_checks.h"
#include "app_core/run_context.h"
#include "bench_cli.h"
#include "grid/box_grid.h"
#include "grid/grdecl_reader.h"
#include "grid/grdecl_writer.h"

namespace {

namespace fs = std::filesystem;
using cutaway::grid::GridDims;

constexpr double kTargetBytesPerCell = 64.0;

struct Options {
    std::string mode = "driver";  // driver | write | load
    fs::path file;
    fs::path dir;
    fs::path json_out;
    GridDims dims{250, 400, 100};
    bool poro = true;
    bool keep = false;
};

/// Registers the flags above on `flags`, bound to `o`.
void add_grid_memory_flags(CLI::App& flags, Options& o) {
    CLI::Option* write = flags.add_option_function<std::string>(
        "--write", [&o](const std::string& file) { o.mode = "write", o.file = file; }, "step 1: build the box and write FILE");
    CLI::Option* load = flags.add_option_function<std::string>(
        "--load", [&o](const std::string& file) { o.mode = "load", o.file = file; }, "step 2: load FILE and report");
    write->excludes(load);
    flags.add_option("--json", o.json_out, "also write the report here (its folders made)");
    flags.add_option("--dir", o.dir, "folder for the driver's box file (default: a temporary one)");
    flags.add_option("--nx", o.dims.nx, "box cells along I")->check(cutaway::app::finite_in(1, 100000));
    flags.add_option("--ny", o.dims.ny, "box cells along J")->check(cutaway::app::finite_in(1, 100000));
    flags.add_option("--nz", o.dims.nz, "box cells along K")->check(cutaway::app::finite_in(1, 100000));
    flags.add_flag("!--no-poro", o.poro, "no PORO property");
    flags.add_flag("--keep", o.keep, "keep the driver's box file");
}

/// A "VmXXX:   1234 kB" line of /proc/self/status, in bytes (0 if absent).
double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string utc_now() {
    const std::time_t now = std::time(nullptr);
    std::tm tm{};
    ::gmtime_r(&now, &tm);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &tm);
    return text;
}

nlohmann::json machine_context() {
    return {{"git_revision", cutaway::run_context::git_revision()},
            {"uname", cutaway::run_context::uname_text()},
            {"nproc", ::sysconf(_SC_NPROCESSORS_ONLN)},
            {"date_utc", utc_now()},
            {"build_type", CUTAWAY_BUILD_TYPE},
            {"cxx_flags", CUTAWAY_CXX_FLAGS},
            {"LP_NUM_THREADS", std::getenv("LP_NUM_THREADS") ? nlohmann::json(std::getenv("LP_NUM_THREADS"))
                                                              : nlohmann::json(nullptr)}};
}

int run_write(const Options& o) {
    const auto start = std::chrono::steady_clock::now();
    cutaway::grid::BoxGridSpec spec;
    spec.dims = o.dims;
    spec.cell_size = {25.0, 25.0, 2.0};
    spec.origin = {0.0, 0.0, 1500.0};
    cutaway::grid::CornerPointGrid grid = cutaway::grid::make_box_grid(spec);
    if (o.poro) grid.set_property("PORO", std::vector<float>(grid.cell_count(), 0.25f));
    cutaway::grid::GrdeclWriteOptions options;
    options.header_comments = {"bench_grid_memory box: " + std::to_string(o.dims.nx) + "x" + std::to_string(o.dims.ny) +
                               "x" + std::to_string(o.dims.nz) + ", vertical pillars, flat layers" +
                               (o.poro ? ", constant PORO" : "")};
    cutaway::grid::write_grdecl(o.file, grid, options);
    std::cerr << "bench_grid_memory: wrote " << o.file << " (" << fs::file_size(o.file) << " bytes, "
              << grid.cell_count() << " cells) in " << seconds_since(start) << " s\n";
    return 0;
}

int run_load(const Options& o) {
    // Baseline first: nothing big has been touched yet in this fresh process.
    const std::size_t hwm_before = cutaway::run_context::proc_status_bytes("VmHWM");
    const std::size_t rss_before = cutaway::run_context::proc_status_bytes("VmRSS");
    const auto start = std::chrono::steady_clock::now();
    const cutaway::grid::CornerPointGrid grid = cutaway::grid::load_grdecl({o.file});
    const double load_seconds = seconds_since(start);
    const std::size_t hwm_after = cutaway::run_context::proc_status_bytes("VmHWM");
    const std::size_t rss_after = cutaway::run_context::proc_status_bytes("VmRSS");

    const double cells = double(grid.cell_count());
    const std::size_t peak = hwm_after - hwm_before;
    const std::size_t resident = rss_after > rss_before ? rss_after - rss_before : 0;
    const std::size_t geometry = grid.geometry_bytes();
    const std::size_t properties = grid.property_bytes();
    const double peak_per_cell = double(peak) / cells;
    const double geometry_per_cell = double(geometry) / cells;
    const double properties_per_cell = double(properties) / cells;
    const double peak_less_properties_per_cell = (double(peak) - double(properties)) / cells;

    nlohmann::json result = {
        {"benchmark", "bench_grid_memory"},
        {"context", machine_context()},
        {"file", o.file.string()},
        {"file_bytes", fs::file_size(o.file)},
        {"dims", {grid.dims().nx, grid.dims().ny, grid.dims().nz}},
        {"cells", grid.cell_count()},
        {"active_cells", grid.active_count()},
        {"zcorn_compact", grid.zcorn().is_compact()},
        {"properties", grid.property_names()},
        {"load_seconds", load_seconds},
        {"vmhwm_before_bytes", hwm_before},
        {"vmhwm_after_bytes", hwm_after},
        {"vmrss_before_bytes", rss_before},
        {"vmrss_after_bytes", rss_after},
        {"peak_bytes", peak},
        {"resident_bytes", resident},
        {"geometry_bytes", geometry},
        {"property_bytes", properties},
        {"bytes_per_cell",
         {{"geometry", geometry_per_cell},
          {"properties", properties_per_cell},
          {"peak", peak_per_cell},
          {"peak_less_properties", peak_less_properties_per_cell},
          {"resident", double(resident) / cells}}},
        {"target_bytes_per_cell_plus_properties", kTargetBytesPerCell},
        {"meets_target",
         {{"geometry", geometry_per_cell <= kTargetBytesPerCell},
          {"peak", peak_less_properties_per_cell <= kTargetBytesPerCell}}},
    };
    const std::string text = result.dump(2);
    std::cout << text << "\n";
    if (!o.json_out.empty()) {
        if (o.json_out.has_parent_path()) fs::create_directories(o.json_out.parent_path());
        std::ofstream(o.json_out) << text << "\n";
    }
    std::fprintf(stderr,
                 "bench_grid_memory: %zu cells loaded in %.2f s; geometry %.2f B/cell, properties %.2f B/cell, "
                 "peak %.2f B/cell (%.2f less properties); target %.0f B/cell + properties: %s\n",
                 grid.cell_count(), load_seconds, geometry_per_cell, properties_per_cell, peak_per_cell,
                 peak_less_properties_per_cell, kTargetBytesPerCell,
                 peak_less_properties_per_cell <= kTargetBytesPerCell && geometry_per_cell <= kTargetBytesPerCell
                     ? "met"
                     : "NOT met");
    if (peak_less_properties_per_cell > kTargetBytesPerCell)
        std::cerr << "bench_grid_memory: WARNING peak " << peak_less_properties_per_cell
                  << " bytes/cell (less properties) exceeds the target of " << kTargetBytesPerCell << "\n";
    return 0;
}

/// Runs this program again with `args` in a child process; its exit status.
int run_child(const std::vector<std::string>& args) {
    std::vector<char*> argv;
    std::string self = "/proc/self/exe";
    argv.push_back(self.data());
    std::vector<std::string> copy = args;
    for (std::string& a : copy) argv.push_back(a.data());
    argv.push_back(nullptr);
    std::cout.flush();
    std::cerr.flush();
    const pid_t pid = ::fork();
    if (pid < 0) throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
    if (pid == 0) {
        ::execv("/proc/self/exe", argv.data());
        std::perror("bench_grid_memory: execv");
        ::_exit(127);
    }
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) throw std::runtime_error(std::string("waitpid: ") + std::strerror(errno));
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

int run_driver(const Options& o) {
    const bool own_dir = o.dir.empty();
    const fs::path dir = own_dir ? fs::temp_directory_path() / ("cutaway_bench_grid_memory_" + std::to_string(::getpid()))
                                 : o.dir;
    fs::create_directories(dir);
    const fs::path file = dir / ("box_" + std::to_string(o.dims.nx) + "x" + std::to_string(o.dims.ny) + "x" +
                                 std::to_string(o.dims.nz) + ".grdecl");
    std::vector<std::string> write_args = {"--write", file.string(), "--nx", std::to_string(o.dims.nx),
                                           "--ny", std::to_string(o.dims.ny), "--nz", std::to_string(o.dims.nz)};
    if (!o.poro) write_args.push_back("--no-poro");
    int rc = run_child(write_args);
    if (rc == 0) {
        std::vector<std::string> load_args = {"--load", file.string()};
        if (!o.json_out.empty()) load_args.insert(load_args.end(), {"--json", o.json_out.string()});
        rc = run_child(load_args);
    }
    if (!o.keep) {
        std::error_code ignored;
        fs::remove(file, ignored);
        if (own_dir) fs::remove(dir, ignored);
    }
    return rc;
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    CLI::App flags{"Peak memory of loading a box GRDECL with our reader", "bench_grid_memory"};
    add_grid_memory_flags(flags, o);
    if (const std::optional<int> exit_code = cutaway::bench::parse_flags(flags, argc, argv, cutaway::bench::Arguments::all_ours))
        return *exit_code;
    try {
        if (o.mode == "write") return run_write(o);
        if (o.mode == "load") return run_load(o);
        return run_driver(o);
    } catch (const std::exception& e) {
        std::cerr << "bench_grid_memory: " << e.what() << "\n";
        return 1;
    }
}

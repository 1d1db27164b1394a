#pragma once
// A benchmark program's own flags through CLI11, in the spellings the experiments and scripts pass
// (`--presets=a,b`, `--size=1920x1080`, `--ssao=0`, `--preset NAME`), checked while parsing with
// the validators of `cutaway` (app_core/option_checks.h) and the project's name tables, before any model
// is loaded or GL context made. Google Benchmark's own arguments (`--benchmark_*`, `--v=N`) are
// left in argv for benchmark::Initialize; `--help` prints the program's flags, then Google
// Benchmark's.
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace cutaway::bench {

/// Whether `argument` belongs to Google Benchmark: `--benchmark_*` or its verbosity `--v=N`.
bool is_google_benchmark_argument(const std::string& argument);

/// Which arguments `parse_flags` hands to CLI11.
enum class Arguments {
    with_google_benchmark,  ///< Google Benchmark's stay in argv (argc updated), the rest are the program's
    all_ours,               ///< a program without Google Benchmark: every argument is the program's
};

/// Whether `parse_flags` prints help and refusals (an MPI rank other than 0 parses silently).
enum class Messages { print, silent };

/// Parses `argv` with `flags` (the program's own options, its name the program's). Returns the
/// exit code when the program should stop now: 0 after --help, 2 after a refused argument (one
/// line on stderr: "PROGRAM: --flag: expected ..., found ..."); nullopt to go on.
std::optional<int> parse_flags(CLI::App& flags, int& argc, char** argv, Arguments arguments = Arguments::with_google_benchmark,
                               Messages messages = Messages::print);

/// Registers `name` taking "AxB" or "AxBxC" (as many parts as `values`; e.g. --size=1920x1080
/// with format "WxH"): each part a whole number in [low, high] `unit`, stored through `values`.
CLI::Option* add_dims_option(CLI::App& flags, const std::string& name, const std::vector<int*>& values, int low, int high,
                             const std::string& format, const std::string& unit, const std::string& help);

/// The model presets' names (`preset:NAME`, generators/presets.h), for one_of checks.
std::vector<std::string> model_preset_names();

}  // namespace cutaway::bench

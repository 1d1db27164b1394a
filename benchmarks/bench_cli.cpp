#include "bench_cli.h"

#include <algorithm>
#include <charconv>
#include <iostream>
#include <sstream>

#include <benchmark/benchmark.h>

#include "generators/presets.h"

namespace cutaway::bench {

bool is_google_benchmark_argument(const std::string& argument) {
    return argument.rfind("--benchmark_", 0) == 0 || argument.rfind("--v=", 0) == 0;
}

std::optional<int> parse_flags(CLI::App& flags, int& argc, char** argv, Arguments arguments, Messages messages) {
    std::vector<std::string> ours;
    int kept = 1;
    for (int a = 1; a < argc; ++a) {
        const std::string argument = argv[a];
        if (arguments == Arguments::with_google_benchmark && is_google_benchmark_argument(argument)) argv[kept++] = argv[a];
        else ours.push_back(argument);
    }
    argc = kept;
    for (CLI::Option* option : flags.get_options())  // help shows each default (the values bound before parsing)
        if (option->get_default_str().empty()) option->capture_default_str();
    const std::string program = flags.get_name();
    flags.failure_message([program](const CLI::App*, const CLI::Error& error) {
        return program + ": " + error.what() + " (" + program + " --help lists the flags)\n";
    });
    if (arguments == Arguments::with_google_benchmark)
        flags.footer("Google Benchmark's flags (--benchmark_*, --v=N) pass through; they follow.");
    std::reverse(ours.begin(), ours.end());  // CLI11 takes the arguments last first
    try {
        flags.parse(ours);
    } catch (const CLI::ParseError& error) {
        // A refused argument is bad input (exit 2) whatever CLI11's own code; --help stays 0.
        std::ostringstream silenced;
        const bool print = messages == Messages::print;
        if ((print ? flags.exit(error) : flags.exit(error, silenced, silenced)) != 0) return 2;
        if (print && arguments == Arguments::with_google_benchmark) {
            std::cout << "\n" << std::flush;
            benchmark::PrintDefaultHelp();
        }
        return 0;
    }
    return std::nullopt;
}

namespace {

/// `text` split at each 'x' into whole numbers in [low, high]; nullopt when it is not that.
std::optional<std::vector<int>> dims_from_text(const std::string& text, std::size_t parts, int low, int high) {
    std::vector<int> values;
    std::size_t start = 0;
    while (values.size() < parts) {
        const std::size_t end = std::min(text.find('x', start), text.size());
        int value = 0;
        const auto [last, error] = std::from_chars(text.data() + start, text.data() + end, value);
        if (error != std::errc() || last != text.data() + end || value < low || value > high) return std::nullopt;
        values.push_back(value);
        start = end + 1;
    }
    if (start != text.size() + 1) return std::nullopt;  // more parts than expected
    return values;
}

}  // namespace

CLI::Option* add_dims_option(CLI::App& flags, const std::string& name, const std::vector<int*>& values, int low, int high,
                             const std::string& format, const std::string& unit, const std::string& help) {
    const std::size_t parts = values.size();
    const std::string expected = "expected " + format + ", each a whole number in [" + std::to_string(low) + ", " +
                                 std::to_string(high) + "]" + (unit.empty() ? "" : " " + unit);
    const CLI::Validator check(
        [=](std::string& text) -> std::string {
            return dims_from_text(text, parts, low, high) ? "" : expected + ", found '" + text.substr(0, 40) + "'";
        },
        format);
    std::string shown;
    for (const int* value : values) shown += (shown.empty() ? "" : "x") + std::to_string(*value);
    return flags
        .add_option_function<std::string>(
            name,
            [=](const std::string& text) {
                const std::vector<int> dims = *dims_from_text(text, parts, low, high);  // checked above
                for (std::size_t k = 0; k < parts; ++k) *values[k] = dims[k];
            },
            help)
        ->check(check)
        ->default_str(shown);
}

std::vector<std::string> model_preset_names() {
    std::vector<std::string> names;
    for (const generators::GeneratorParameters& preset : generators::presets()) names.push_back(preset.name);
    return names;
}

}  // namespace cutaway::bench

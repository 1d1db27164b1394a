// libFuzzer target: any command line given to `cutaway render`'s option parser is either accepted
// with values its checks hold (finite, in range) or refused with a CLI11 parse error or
// std::invalid_argument naming the option. The input is split into arguments at newlines.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app_core/render_options.h"

namespace {

std::vector<std::string> split_lines(const std::uint8_t* data, std::size_t size) {
    std::vector<std::string> args;
    std::string current;
    for (std::size_t n = 0; n < size; ++n) {
        if (data[n] == '\n') {
            args.push_back(current);
            current.clear();
        } else {
            current += char(data[n]);
        }
    }
    args.push_back(current);
    return args;
}

/// What the validators promise for an accepted command line.
void check_accepted(const cutaway::app::RenderOptions& o) {
    for (float v : o.camera)
        if (!std::isfinite(v)) std::abort();
    if (o.width < 16 || o.height < 16 || o.width > 32768 || o.height > 32768) std::abort();
    if (!(o.memory_limit_gb > 0) || !std::isfinite(o.z_scale) || o.z_scale < 0) std::abort();
    if (o.render_target_bytes() > o.memory_limit_bytes()) std::abort();
    if (o.primary_fraction < 0 || o.primary_fraction > 1 || !std::isfinite(o.primary_fraction)) std::abort();
    for (float v : o.range)
        if (!std::isfinite(v)) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > 4096) return 0;
    cutaway::app::RenderOptions options;
    CLI::App app{"fuzz"};
    cutaway::app::add_render_options(app, options);
    std::vector<std::string> args = split_lines(data, size);
    std::vector<char*> argv{const_cast<char*>("render")};
    for (std::string& a : args) argv.push_back(a.data());
    try {
        app.parse(int(argv.size()), argv.data());
    } catch (const CLI::ParseError&) {
        return 0;
    }
    check_accepted(options);
    try {
        (void)options.frame_settings();
        (void)options.describe();
    } catch (const std::invalid_argument&) {
    }
    return 0;
}

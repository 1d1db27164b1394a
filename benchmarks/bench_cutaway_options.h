#pragma once
// bench_cutaway's own flags (parsed by CLI11 through bench_cli.h before Google Benchmark sees
// argv). Each list is one axis of the benchmark product (`--presets=a,b`); the defaults keep the
// product small (the paper's Table 1 setup).
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app_core/option_checks.h"
#include "bench_cli.h"
#include "cutaway/cut_surface/cut_strategy_choice.h"
#include "cutaway/cut_surface/cut_surface_registry.h"
#include "cutaway/setting_names.h"

namespace cutaway::bench {

struct CutawayBenchOptions {
    std::vector<std::string> presets{"zaphirus", "petra", "opharine", "sapphire"};
    std::vector<double> fractions{0.01};           ///< primary fraction of active cells
    std::vector<std::string> strategies{"all"};    ///< registry names, or "all"
    std::vector<std::string> borders{"raycast"};   ///< BorderMode names (setting_names.h)
    std::vector<int> mean_filters{9};              ///< k x k, 0 = off
    std::vector<std::string> draws{"visible"};     ///< stage 2 faces: DrawMode names
    /// Full opening angles (horizontal = vertical), degrees 0..180, as `cutaway render --aperture`
    /// takes them; empty = each pose's own aperture along the camera path (camera_path.h).
    std::vector<int> apertures;
    /// Strategies whose CPU reference BM_cpu_path times ("all" = every chosen GPU strategy
    /// that has one, "none" = no BM_cpu_path).
    std::vector<std::string> cpu_references{"all"};
    int width = 1920, height = 1080;
    int poses = 8;                                 ///< camera path length (camera_path.h)
    bool per_pose = false;                         ///< one benchmark per pose instead of the whole path
    bool ssao = true;                              ///< SSAO in every frame (--ssao=0: off, for stage-1 sweeps)
    bool baseline = true;                          ///< time the plain frame of the same poses too (--baseline=0: skip)
    int warmup = 1;                                ///< untimed passes over the path first
    int repeat = 1;                                ///< timed passes over the path (each pose repeat times)
};

/// The cut-surface registry's names, in its order.
inline std::vector<std::string> registry_strategy_names() {
    std::vector<std::string> names;
    for (const pipeline::CutSurfaceEntry& entry : pipeline::cut_surface_strategies()) names.push_back(entry.name);
    return names;
}

/// `first` followed by `rest`.
inline std::vector<std::string> joined(std::vector<std::string> first, const std::vector<std::string>& rest) {
    first.insert(first.end(), rest.begin(), rest.end());
    return first;
}

/// Registers the flags above on `flags`, bound to `options`; each value is checked while parsing
/// (choices from the project's name tables and the registry, numbers in the ranges `cutaway render` takes).
inline void add_cutaway_bench_flags(CLI::App& flags, CutawayBenchOptions& options) {
    using app::finite_above, app::finite_in, app::one_of;
    flags.add_option("--presets", options.presets, "models (preset:NAME), each loaded once")
        ->delimiter(',')->check(one_of(model_preset_names()));
    flags.add_option("--fractions", options.fractions, "primary fractions of the active cells")
        ->delimiter(',')->check(finite_above(0, 1));
    flags.add_option("--strategies", options.strategies, "cut-surface strategies: all, auto or registry names")
        ->delimiter(',')->check(one_of(joined({"all"}, pipeline::cut_strategy_names())));
    const std::vector<std::string> borders = pipeline::choice_names<pipeline::BorderMode>();
    flags.add_option("--borders", options.borders, pipeline::joined_choices(borders) + ": border lines")
        ->delimiter(',')->check(one_of(borders));
    flags.add_option("--mean_filters", options.mean_filters, "mean filter sizes k (0 = off)")
        ->delimiter(',')->check(finite_in(0, 65));
    const std::vector<std::string> draws = pipeline::choice_names<pipeline::DrawMode>();
    flags.add_option("--draws", options.draws, pipeline::joined_choices(draws) + ": faces stage 2 draws")
        ->delimiter(',')->check(one_of(draws));
    flags.add_option("--apertures", options.apertures,
                     "full opening angles, degrees (default: each pose's own along the camera path)")
        ->delimiter(',')->check(finite_in(0, 180, "degrees"));
    flags.add_option("--cpu_references", options.cpu_references,
                     "strategies BM_cpu_path times against their CPU path: all, none or registry names")
        ->delimiter(',')->check(one_of(joined({"all", "none"}, registry_strategy_names())));
    add_dims_option(flags, "--size", {&options.width, &options.height}, 16, 32768, "WxH", "pixels", "image size");
    flags.add_option("--poses", options.poses, "camera path length")->check(finite_in(1, 1000));
    flags.add_flag("--per_pose", options.per_pose, "one benchmark per pose instead of the whole path");
    flags.add_flag("--ssao", options.ssao, "SSAO in every frame (--ssao=0: off)");
    flags.add_flag("--baseline", options.baseline, "time the plain frame of the same poses too (--baseline=0: skip)");
    flags.add_option("--warmup", options.warmup, "untimed passes over the path first")->check(finite_in(0, 100));
    flags.add_option("--repeat", options.repeat, "timed passes over the path")->check(finite_in(1, 1000));
}

}  // namespace cutaway::bench

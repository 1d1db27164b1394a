#pragma once
// "auto", the default cut-surface strategy: it is not a method of its own but picks one of the
// registry's per frame from the number of primary cells (summed over renderers when a frame runs
// across several): frustum-clusters below a threshold, frustum-sweep from there. Both keep every
// primary pixel exposed and both draw the union of the primaries' frustums (frustum-sweep equals
// the rasterised union up to rounding: tests/gl/frustum_sweep_gl_test.cpp). The threshold is the
// crossover of their stage 1 times on the kind of GL device running the frame (1920x1080,
// medians, results/cut_strategies and README):
//   - frustum-clusters draws one frustum per IJK box of primaries: cheapest while the boxes are
//     few; its wall area grows with them (scale-10m's 93,100 primaries: very slow on llvmpipe);
//   - frustum-sweep costs O(pixels) whatever the count;
//   - on a GPU (the H100 and the H200) clusters is cheaper up to petra's 6,095 primaries and
//     sweep from sapphire's 9,691 on: 10,000;
//   - on a software rasteriser (llvmpipe), which pays for every wall pixel on the CPU, sweep is
//     cheaper from 350-700 primaries (sweep on opharine's 707, clusters on zaphirus's 349): 500.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace cutaway::pipeline {

inline constexpr const char* auto_cut_strategy = "auto";
inline constexpr std::uint64_t auto_sweep_from_primaries_on_gpu = 10000;
inline constexpr std::uint64_t auto_sweep_from_primaries_on_cpu = 500;

/// Whether GL_RENDERER names a rasteriser that runs on the CPU (llvmpipe, softpipe, SwiftShader).
bool is_software_rasteriser(std::string_view gl_renderer);

/// The primary cells from which "auto" picks frustum-sweep on the device named by GL_RENDERER.
std::uint64_t auto_sweep_from_primaries(std::string_view gl_renderer);

/// `name` itself, or for "auto" the registry strategy it picks for `primaries` primary cells with
/// frustum-sweep from `sweep_from` primaries.
std::string resolve_cut_strategy(const std::string& name, std::uint64_t primaries, std::uint64_t sweep_from);

/// How "auto" chooses, in words (stats.json's strategy.chosen_by).
std::string auto_choice_rule(std::uint64_t sweep_from);

/// "auto" and then every registry name (the viewer's choices, the CLI's help).
std::vector<std::string> cut_strategy_names();

}  // namespace cutaway::pipeline

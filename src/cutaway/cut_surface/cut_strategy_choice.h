#pragma once
// "auto", the default cut-surface strategy: it is not a method of its own but picks one of the
// registry's per frame from the number of primary cells (summed over renderers when a frame runs
// across several): frustum-clusters below auto_sweep_from_primaries, frustum-sweep from there.
// Both keep every primary pixel exposed. Why 10,000 (stage 1 at 1920x1080, medians, README):
//   - frustum-clusters draws one frustum per IJK box of primaries: cheapest while the boxes are
//     few; its wall area grows with them (scale-10m's 93,100 primaries: 9.5 s on llvmpipe);
//   - frustum-sweep costs O(pixels) whatever the count;
//   - on the H100 and the H200 clusters is cheaper up to petra's 6,095 primaries and sweep from
//     sapphire's 9,691 on; on llvmpipe sweep is already cheaper from about 350-700 primaries, but
//     10,000 keeps the main job (1% primaries: 70-1,938 cells on the four presets) on clusters on
//     every device.
#include <cstdint>
#include <string>
#include <vector>

namespace cutaway::pipeline {

inline constexpr const char* auto_cut_strategy = "auto";
inline constexpr std::uint64_t auto_sweep_from_primaries = 10000;

/// `name` itself, or for "auto" the registry strategy it picks for `primaries` primary cells.
std::string resolve_cut_strategy(const std::string& name, std::uint64_t primaries);

/// "auto" and then every registry name (the viewer's choices, the CLI's help).
std::vector<std::string> cut_strategy_names();

}  // namespace cutaway::pipeline

#pragma once
// What `cutaway render` reports, shared by the single-process and the distributed run
// (render_command.cpp, distributed_render.cpp): stage medians, faces drawn, metrics, view checks.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app_core/render_options.h"
#include "cutaway/cutaway_renderer.h"
#include "io/file_identity.h"

namespace cutaway::app {


/// Median over repetitions of each stage's wall and query times (pipeline::stage_names, then
/// `extra_stages`, then total), plus validity of all.
nlohmann::json stage_statistics(const std::vector<pipeline::FrameTimes>& runs, const std::vector<std::string>& extra_stages = {});

nlohmann::json faces_drawn_json(const pipeline::FacesDrawn& drawn);

/// stats.json "strategy": the registry strategy that drew the cut (`drawn`), and what was asked
/// for (`requested`: its own name, or "auto" with the rule it picked by: frustum-sweep from
/// `auto_sweep_from` primaries).
nlohmann::json strategy_json(const pipeline::CutSurfaceEntry& drawn, const std::string& requested, std::uint64_t auto_sweep_from);

/// A metric's value, or null with KEY_absent saying why when its denominator is zero (0/0 is not 1).
void put_metric(nlohmann::json& stats, const std::string& key, double fraction, std::size_t denominator,
                const std::string& why_absent);

/// --out, --cell-ids and --stats (empty: not given), for the overwrite checks.
std::vector<io::NamedFile> render_outputs(const RenderOptions& options);

/// Refuses --out, --cell-ids and --stats naming a model file or each other, however spelled (by
/// file identity): checked before the model is read (on rank 0 alone under mpirun).
void refuse_render_overwrites(const RenderOptions& options);

/// Refuses a camera that would see nothing: a model without extent (all pillars at one x, y, or
/// coordinates whose extent overflows single precision), a DIST inside the model, or a --camera
/// DIST so far that the model covers under a pixel.
void check_view(const pipeline::ModelFrame& frame, const RenderOptions& options);

/// Refuses --only primaries when no cell is a primary (`selected_name`'s cells in `range`): the
/// frame would hold nothing but the outline.
void refuse_nothing_to_draw(const RenderOptions& options, std::size_t primary_count, const std::string& selected_name,
                            const grid::PrimaryRange& range);

}  // namespace cutaway::app

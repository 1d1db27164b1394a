#pragma once
// The passes of one cutaway frame, decided once from the settings and the renderer's state
// (DESIGN.md "A frame is a plan"), in the spirit of Filament's frame graph kept small: each pass
// declares the targets it reads and writes, passes are grouped into the timed stages named in
// stats.json, and the renderer runs the plan in a straight line. Freeze view, see-through, the mean
// filter and the distributed combine are entries here, never branches in the frame function.
#include <cstdint>
#include <string>
#include <vector>

#include "cutaway/frame_settings.h"

namespace cutaway::pipeline {

/// One pass of the frame, in the order they can run.
enum class FramePass {
    clear_cut,           ///< the cut's depth image cleared to "nothing cut"
    strategy_cut,        ///< the cut-surface strategy draws the primaries' cut (stage 1)
    volume_cut,          ///< the user's cut volumes drawn into the same cut by the same max (stage 1)
    opening_cut,         ///< smooth coherence: cells opening or closing their cut, same max (stage 1;
                         ///< the seed strategies draw them among their seeds instead)
    rear_shell,          ///< the model's rear shell seen from the cut camera (the clamp)
    combine_cut,         ///< distributed: per-pixel max of the cut and rear shell over all renderers
    resolve_cut,         ///< normals and rear-shell clamp of the unfiltered cut into the cut surface
    filter_resolve_cut,  ///< mean filter of the cut, then its normals and clamp into the cut surface
    culling,             ///< the visible path's pyramid and face selection
    secondary_list,      ///< the paper's path: every secondary face listed (built once per selection)
    view_rear_shell,     ///< freeze view: the rear shell seen from the model camera, kept by stage 2
    clear_scene,         ///< the G-buffer cleared and bound, the depth test set up
    secondaries,         ///< stage 2: clipped secondaries, cut fill, wireframe and borders
    bind_scene,          ///< the G-buffer bound again for stage 3
    primaries,           ///< stage 3: primary cells with their own edge colour
    hidden_primary_walls,  ///< stage 3, --only secondaries: the hidden primaries' far walls (grey)
    wells,               ///< stage 3: well tubes, never cut (drawn by every renderer of a distributed frame)
    shell_contours,      ///< stage 3: shell contours and shell-cut lines
    reset_depth_test,    ///< depth test back to GL_LESS after the scene
    combine_scene,       ///< distributed: the G-buffer composited over all renderers
    ssao,                ///< ambient occlusion over the G-buffer
    composite,           ///< shading, saturation, silhouette into the final image
    colour_bar,          ///< the colour bar onto the final image
    well_labels,         ///< each well's name beside its wellhead, onto the final image
    caption,             ///< a line of text at the top-left corner (an animation's date), onto the final image
};

/// Images a pass reads or writes (bit flags).
inline constexpr std::uint32_t target_cut_depth = 1u << 0;    ///< the strategy's cut depth (CutTargets::depth)
inline constexpr std::uint32_t target_rear_shell = 1u << 1;   ///< the rear shell's depth (RearShellDepth)
inline constexpr std::uint32_t target_cut_surface = 1u << 2;  ///< the resolved cut stage 2 reads (surface, normals)
inline constexpr std::uint32_t target_faces = 1u << 3;        ///< stage 2's faces (culling output or secondary list)
inline constexpr std::uint32_t target_scene = 1u << 4;        ///< the G-buffer (colour, normal and depth, ids, depth)
inline constexpr std::uint32_t target_occlusion = 1u << 5;    ///< SSAO's occlusion image
inline constexpr std::uint32_t target_final = 1u << 6;        ///< the final RGBA image

struct PassTargets {
    std::uint32_t reads = 0;
    std::uint32_t writes = 0;
};
/// The pass's name in the frame plan's JSON and in GL debug groups.
const char* to_string(FramePass pass);

/// What the plan needs to know of the renderer beyond the settings.
struct RendererState {
    bool frozen = false;             ///< freeze view is on
    bool frozen_cut_valid = false;   ///< the frozen camera's cut is made and still holds
    bool cone_field_strategy = false;  ///< the frame's strategy combines its seeds, not its cut
    bool cut_volumes = false;        ///< cut volumes are set (CutawayRenderer::set_cut_volumes)
    bool opening_cells = false;      ///< cells open their cut (CutawayRenderer::set_opening_cells)
    bool distributed = false;        ///< hooks combine the frame over several renderers
    bool screen_passes = true;       ///< this renderer runs SSAO and post (false: a rank other than 0)
    bool wells = false;              ///< the renderer holds well tubes to draw
};

/// A group of passes timed together under one stats.json stage name; `stage` empty: untimed work
/// (built once, not part of a frame's time).
struct PlannedStage {
    std::string stage;
    std::vector<FramePass> passes;
};

struct FramePlan {
    std::vector<PlannedStage> stages;
    /// Stage 1 runs this frame (false while a frozen cut is kept).
    bool makes_cut = false;
    /// The strategy combines its seeds through the hooks inside strategy_cut (cone fields).
    bool combine_seeds = false;
    /// combine_cut's images: the cut (unless its seeds were combined) and the rear shell.
    bool combine_cut_depth = false;
    bool combine_rear_shell = false;
    /// Stage 2 clips against the model camera's rear shell (freeze view with a clamped cut).
    bool clip_view_rear_shell = false;
    /// Stage 2 draws (`--only` is not primaries), through a cut (not --no-cut); stage 3's primaries.
    bool cut_needed = false;
    bool cut_drawn = false;
    bool draw_primaries = false;
    /// The cut is clamped in front of the rear shell (not see-through).
    bool clamp_to_rear_shell = false;

    bool runs(FramePass pass) const;
    /// {"stage": [passes...], ...} in order, for stats.json and logs.
    std::vector<std::string> describe() const;
};

/// The frame's passes for `settings` and `state`.
FramePlan plan_frame(const FrameSettings& settings, const RendererState& state);

/// What `pass` reads and writes in `plan` (the cut's passes read the rear shell only when clamped).
PassTargets targets_of(FramePass pass, const FramePlan& plan);

/// The first pass of `plan` that reads a target no earlier pass wrote (targets kept across frames
/// excepted: the frozen cut and its rear shell), as "pass reads target"; empty if the plan is
/// consistent.
std::string first_unwritten_read(const FramePlan& plan);

}  // namespace cutaway::pipeline

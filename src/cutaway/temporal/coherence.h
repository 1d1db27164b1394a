#pragma once
// How an animation over report steps moves from one step to the next (issue 44): the paper's
// behaviour (`none`) or the time-coherent one (`smooth`). No OpenGL here.
#include <cstddef>
#include <string>
#include <vector>

namespace cutaway::temporal {

enum class Coherence {
    /// A report step's values shown until the next step, the primaries selected anew at each
    /// frame: everything that changes between two steps changes at once at the boundary.
    none,
    /// Values interpolated linearly in time between report steps and primaries kept by
    /// hysteresis (PrimaryTracker): cells enter and leave one by one as their values cross.
    smooth,
};

/// The names the CLI, stats.json and the viewer use.
const char* to_string(Coherence coherence);
/// Every mode's name, in the table's order (the CLI's choices, the viewer's combo).
std::vector<std::string> coherence_names();
/// Throws std::invalid_argument "--coherence 'x': expected none|smooth".
Coherence parse_coherence(const std::string& name);

/// Frame `frame` of an animation over report steps first..last (inclusive) with
/// `frames_per_step` frames from each step to the next: (last - first) x frames_per_step + 1
/// frames, the first at step `first`, the last at step `last`.
struct AnimationTimeline {
    std::size_t first_step = 0;
    std::size_t last_step = 0;
    std::size_t frames_per_step = 1;

    std::size_t frame_count() const { return (last_step - first_step) * frames_per_step + 1; }
    /// The frame's time as a fractional report step (first_step + frame / frames_per_step).
    double time_step(std::size_t frame) const { return double(first_step) + double(frame) / double(frames_per_step); }
};

/// The report steps a frame's values come from: (1 - weight) x lower + weight x upper.
struct StepBlend {
    std::size_t lower = 0;
    std::size_t upper = 0;
    float weight = 0;  ///< of `upper`, in [0, 1)
};

/// `none`: the last report step at or before the frame's time (weight 0). `smooth`: the two
/// steps around it, weighted by the frame's position between them.
StepBlend blend_at(const AnimationTimeline& timeline, std::size_t frame, Coherence coherence);

}  // namespace cutaway::temporal

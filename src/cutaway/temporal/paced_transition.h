#pragma once
// Smooth coherence between two report steps: the cells whose primary membership differs between
// the steps change one by one, at times spread evenly over the interval, in the order in which
// their linearly interpolated values cross the range limit. Linear interpolation alone keeps the
// pops in a burst where a front jumps (a shock front: every swept cell goes from connate to
// front saturation in one step and crosses a limit at about the same fraction of the step);
// pacing by rank turns n changes into about n / frames_per_step per frame. Each changing cell's
// value is warped in time so that it crosses the limit exactly when the cell changes. No OpenGL.
#include <cstdint>
#include <vector>

#include "grid/primary_selection.h"

namespace cutaway::temporal {

class PacedTransition {
public:
    PacedTransition() = default;
    /// `lower`, `upper`: one value per cell at the two report steps; `was`, `is`: the primary
    /// flags there (PrimaryTracker); `range`: the primary range and `band` its hysteresis
    /// widening (property units), which give the limit each changing cell crosses.
    PacedTransition(const std::vector<float>& lower, const std::vector<float>& upper, const std::vector<std::uint8_t>& was,
                    const std::vector<std::uint8_t>& is, const grid::PrimaryRange& range, float band);

    /// Cells whose membership changes between the two steps.
    std::size_t changing_cells() const { return changing_; }
    /// Flags at `weight` in [0, 1] of the way from the lower step: a changing cell takes its upper
    /// step's flag once weight reaches its paced time, every other keeps its flag.
    void flags_at(float weight, const std::vector<std::uint8_t>& was, const std::vector<std::uint8_t>& is,
                  std::vector<std::uint8_t>& flags) const;
    /// Values at `weight`: (1 - g) x lower + g x upper, g = weight for a cell that keeps its
    /// membership; for a changing cell g maps [0, paced time] onto [0, crossing] and
    /// [paced time, 1] onto [crossing, 1], so its value meets the limit as it changes.
    void values_at(float weight, const std::vector<float>& lower, const std::vector<float>& upper,
                   std::vector<float>& values) const;

private:
    /// Per cell: the paced time in (0, 1) of a changing cell, negative for the others.
    std::vector<float> paced_;
    /// Per cell: where its linear interpolation crosses its limit, in [0, 1] (changing cells).
    std::vector<float> crossing_;
    std::size_t changing_ = 0;
};

}  // namespace cutaway::temporal

// Time-coherent animations on the CPU (issue 44): the timeline, hysteresis, paced transitions
// and the frame sequence of both coherence modes, on a shock front moving through a box model.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <utility>

#include "cutaway/temporal/coherence.h"
#include "cutaway/temporal/coherent_sequence.h"
#include "cutaway/temporal/cell_openings.h"
#include "cutaway/temporal/paced_transition.h"
#include "cutaway/temporal/primary_tracker.h"
#include "grid/box_grid.h"
#include "metrics/temporal_metrics.h"

namespace cutaway::temporal {
namespace {

/// Steps held in vectors: what a restart reader hands the animation.
class VectorSteps final : public StepValueSource {
public:
    explicit VectorSteps(std::vector<std::vector<float>> steps) : steps_(std::move(steps)) {}
    const std::string& property() const override { return name_; }
    std::size_t step_count() const override { return steps_.size(); }
    std::vector<float> values(std::size_t step) const override {
        ++reads_;
        return steps_.at(step);
    }
    std::size_t reads() const { return reads_; }

private:
    std::string name_ = "SWAT";
    std::vector<std::vector<float>> steps_;
    mutable std::size_t reads_ = 0;
};

grid::CornerPointGrid front_grid() {
    grid::BoxGridSpec spec;
    spec.dims = {32, 4, 2};
    return grid::make_box_grid(spec);
}

/// A shock front along i, like the generator's flood: ahead of it connate water (0.15), behind it
/// at least the front saturation (0.55), rising by 0.05 per cell behind the front up to 0.8. The
/// front moves 5 cells per step, so every swept cell jumps from 0.15 to >= 0.55 within one step.
std::vector<std::vector<float>> shock_front(const grid::CornerPointGrid& grid, int steps) {
    std::vector<std::vector<float>> result;
    for (int step = 0; step < steps; ++step) {
        const int front = 3 + 5 * step;
        std::vector<float> values(grid.cell_count());
        for (std::size_t c = 0; c < values.size(); ++c) {
            const int i = grid::cell_ijk(grid.dims(), c).i;
            values[c] = i < front ? std::min(0.8f, 0.55f + 0.05f * float(front - 1 - i)) : 0.15f;
        }
        result.push_back(std::move(values));
    }
    return result;
}

TEST(AnimationTimeline, FramesRunFromFirstToLastStep) {
    const AnimationTimeline timeline{2, 5, 4};
    EXPECT_EQ(timeline.frame_count(), 13u);
    EXPECT_DOUBLE_EQ(timeline.time_step(0), 2.0);
    EXPECT_DOUBLE_EQ(timeline.time_step(5), 3.25);
    EXPECT_DOUBLE_EQ(timeline.time_step(12), 5.0);
    const AnimationTimeline single{3, 3, 4};
    EXPECT_EQ(single.frame_count(), 1u);
}

TEST(AnimationTimeline, NoneHoldsTheStepSmoothBlendsTheNext) {
    const AnimationTimeline timeline{2, 5, 4};
    const StepBlend held = blend_at(timeline, 5, Coherence::none);
    EXPECT_EQ(held.lower, 3u);
    EXPECT_EQ(held.upper, 3u);
    EXPECT_EQ(held.weight, 0.0f);
    const StepBlend blended = blend_at(timeline, 5, Coherence::smooth);
    EXPECT_EQ(blended.lower, 3u);
    EXPECT_EQ(blended.upper, 4u);
    EXPECT_FLOAT_EQ(blended.weight, 0.25f);
    const StepBlend last = blend_at(timeline, 12, Coherence::smooth);
    EXPECT_EQ(last.lower, 5u);
    EXPECT_EQ(last.weight, 0.0f);
}

TEST(Coherence, NamesRoundTripAndUnknownNamesAreRefused) {
    for (Coherence c : {Coherence::none, Coherence::smooth}) EXPECT_EQ(parse_coherence(to_string(c)), c);
    EXPECT_EQ(coherence_names(), (std::vector<std::string>{"none", "smooth"}));
    try {
        parse_coherence("fast");
        FAIL() << "no exception";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "--coherence 'fast': expected none|smooth");
    }
}

TEST(PrimaryTracker, HysteresisKeepsAPrimaryInsideTheBand) {
    grid::BoxGridSpec spec;
    spec.dims = {3, 1, 1};
    const grid::CornerPointGrid grid = grid::make_box_grid(spec);
    PrimaryTracker kept(grid, "V", {0.5f, 0.6f}, 0.05f);
    PrimaryTracker anew(grid, "V", {0.5f, 0.6f}, 0.0f);
    const std::vector<float> first{0.55f, 0.55f, 0.3f}, second{0.47f, 0.44f, 0.47f};
    EXPECT_EQ(kept.update(first), (std::vector<std::uint8_t>{1, 1, 0}));
    // 0.47 lies within 0.05 below the range: cell 0 stays; cell 1 left the band; cell 2 was not
    // primary, and entering needs the range itself.
    EXPECT_EQ(kept.update(second), (std::vector<std::uint8_t>{1, 0, 0}));
    anew.update(first);
    EXPECT_EQ(anew.update(second), (std::vector<std::uint8_t>{0, 0, 0}));
    EXPECT_THROW(kept.update({NAN, 0.5f, 0.5f}), std::invalid_argument);
    EXPECT_THROW(PrimaryTracker(grid, "V", {0.5f, 0.6f}, -1.0f), std::invalid_argument);
}

/// The openings of one frame as a map from cell to opening (cells not listed: absent).
std::vector<float> opening_by_cell(const CellOpenings& openings, std::size_t cells) {
    std::vector<float> by_cell(cells, 0.0f);
    for (const OpeningCell& cell : openings.openings()) by_cell.at(cell.cell) = cell.opening;
    return by_cell;
}

/// Runs `openings` over `selected` (one frame each), each frame's window the frames ahead as far as
/// `frames_to_open` reaches; `check` sees every frame.
void run_openings(CellOpenings& openings, std::size_t frames_to_open, const std::vector<std::vector<std::uint8_t>>& selected,
                  const std::function<void(std::size_t)>& check) {
    for (std::size_t f = 0; f < selected.size(); ++f) {
        std::vector<const std::vector<std::uint8_t>*> window;
        for (std::size_t k = f; k < selected.size() && k < f + frames_to_open; ++k) window.push_back(&selected[k]);
        openings.next(window);
        check(f);
    }
}

TEST(CellOpenings, AnEntryOpensItsCutBeforeItIsDrawnAndAnExitClosesItAfter) {
    CellOpenings openings(4, {2, 1, 1});
    // Cell 0 selected from the start, cell 1 enters at frame 4, cell 0 leaves at 5.
    const std::vector<std::vector<std::uint8_t>> selected{{1, 0}, {1, 0}, {1, 0}, {1, 0}, {1, 1},
                                                          {0, 1}, {0, 1}, {0, 1}, {0, 1}, {0, 1}};
    // Beside the cut (each cell opens beside the other, drawn): (level / 4)^(3/8). Cell 1's cut
    // opens over the 3 frames before it enters, cell 0's closes over the 3 after it leaves.
    const float q1 = std::pow(0.25f, 0.375f), q2 = std::pow(0.5f, 0.375f), q3 = std::pow(0.75f, 0.375f);
    const std::vector<std::vector<float>> expected{{0, 0},  {0, q1}, {0, q2}, {0, q3}, {0, 0},
                                                   {q3, 0}, {q2, 0}, {q1, 0}, {0, 0},  {0, 0}};
    run_openings(openings, 4, selected, [&](std::size_t f) {
        const std::vector<float> by_cell = opening_by_cell(openings, 2);
        for (std::size_t c = 0; c < 2; ++c) EXPECT_NEAR(by_cell[c], expected[f][c], 1e-6f) << "frame " << f << " cell " << c;
        for (const OpeningCell& cell : openings.openings()) {
            // A selected cell is drawn, its cut open: never among the openings.
            EXPECT_EQ(selected[f][cell.cell], 0) << "frame " << f;
            // The other cell, its face neighbour, is drawn while this one opens or closes.
            EXPECT_TRUE(cell.beside_cut) << "frame " << f;
        }
    });
}

TEST(CellOpenings, ABriefSelectionOpensAheadAShortAbsenceKeepsTheCutAndOneFrameChangesNothing) {
    CellOpenings openings(4, {1, 1, 1});
    // Selected at frame 3 only: its cut opens from frame 0 (3 frames ahead), closes after it.
    const std::vector<std::vector<std::uint8_t>> brief{{0}, {0}, {0}, {1}, {0}, {0}, {0}, {0}, {0}};
    const std::vector<float> levels{1, 2, 3, 0, 3, 2, 1, 0, 0};
    run_openings(openings, 4, brief, [&](std::size_t f) {
        // Alone (no neighbour drawn): its cut opens from where the view rays enter the model.
        EXPECT_NEAR(opening_by_cell(openings, 1)[0], CellOpenings::depth_share(levels[f] / 4.0f, false), 1e-6f) << f;
        for (const OpeningCell& cell : openings.openings()) EXPECT_FALSE(cell.beside_cut);
    });
    // Absent for one frame between two selections: its cut stays fully open meanwhile.
    CellOpenings gap(4, {1, 1, 1});
    const std::vector<std::vector<std::uint8_t>> absent{{1}, {0}, {1}, {1}};
    run_openings(gap, 4, absent, [&](std::size_t f) {
        EXPECT_FLOAT_EQ(opening_by_cell(gap, 1)[0], f == 1 ? 1.0f : 0.0f) << f;
    });
    CellOpenings at_once(1, {2, 1, 1});
    run_openings(at_once, 1, {{1, 0}, {0, 1}, {1, 1}}, [&](std::size_t) { EXPECT_TRUE(at_once.openings().empty()); });
    EXPECT_EQ(frames_to_open(4), 8u);
    EXPECT_EQ(frames_to_open(1), 2u);
    EXPECT_EQ(frames_to_open(3), 6u);
    EXPECT_EQ(frames_to_open(24), CellOpenings::max_frames_to_open);
    EXPECT_THROW(CellOpenings(0, {1, 1, 1}), std::invalid_argument);
    EXPECT_THROW(CellOpenings(CellOpenings::max_frames_to_open + 1, {1, 1, 1}), std::invalid_argument);
    const std::vector<std::uint8_t> one{1}, two{1, 0};
    EXPECT_THROW(at_once.next({&one}), std::invalid_argument);  // one flag for a grid of two cells
    EXPECT_THROW(at_once.next({}), std::invalid_argument);      // no frame
    EXPECT_THROW(at_once.next({&two, &two}), std::invalid_argument);  // a window past its frames to open
}

TEST(PacedTransition, ChangesSpreadEvenlyInCrossingOrderAndValuesMeetTheLimitThen) {
    // Eight cells enter [0.5, 1] from 0.1: their linear crossings are (0.5 - 0.1) / (v1 - 0.1),
    // so cells with a higher upper value cross earlier. Two cells stay out, one stays in.
    const std::vector<float> lower{0.1f, 0.1f, 0.1f, 0.1f, 0.1f, 0.1f, 0.1f, 0.1f, 0.1f, 0.2f, 0.7f};
    const std::vector<float> upper{0.9f, 0.6f, 0.8f, 0.55f, 0.7f, 0.65f, 0.75f, 0.85f, 0.3f, 0.4f, 0.8f};
    const std::vector<std::uint8_t> was{0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1}, is{1, 1, 1, 1, 1, 1, 1, 1, 0, 0, 1};
    const PacedTransition transition(lower, upper, was, is, {0.5f, 1.0f}, 0.0f);
    EXPECT_EQ(transition.changing_cells(), 8u);
    std::vector<std::uint8_t> flags;
    std::size_t before = 0;
    for (int quarter = 1; quarter <= 4; ++quarter) {
        transition.flags_at(0.25f * float(quarter), was, is, flags);
        const std::size_t now = grid::count_primaries(flags) - 1;  // less the cell that stays in
        EXPECT_EQ(now - before, 2u) << "two of eight changes per quarter step";
        before = now;
    }
    // Cell 0 (0.9) crosses first, cell 3 (0.55) last: the paced times keep the crossing order.
    transition.flags_at(0.2f, was, is, flags);
    EXPECT_EQ(flags[0], 1);
    EXPECT_EQ(flags[3], 0);
    // At its paced time a changing cell's value is the limit it crosses; the steps are kept at both
    // ends; unchanged cells move linearly.
    std::vector<float> values;
    transition.values_at(0.0f, lower, upper, values);
    EXPECT_EQ(values, lower);
    transition.values_at(1.0f, lower, upper, values);
    for (std::size_t c = 0; c < values.size(); ++c) EXPECT_NEAR(values[c], upper[c], 1e-6f);
    transition.values_at(1.0f / 16.0f, lower, upper, values);  // cell 0's paced time: (0 + 0.5) / 8
    EXPECT_NEAR(values[0], 0.5f, 1e-6f);
    transition.values_at(0.5f, lower, upper, values);
    EXPECT_NEAR(values[9], 0.3f, 1e-6f);
}

/// pop_max of a whole sequence (drawn flags compared with the frame before); `all` receives each
/// frame's selection.
std::size_t pop_max(CoherentSequence& sequence, std::size_t frames, std::vector<std::vector<std::uint8_t>>* all = nullptr) {
    std::vector<std::uint8_t> previous;
    std::size_t most = 0;
    for (std::size_t f = 0; f < frames; ++f) {
        const CoherentSequence::Frame frame = sequence.next();
        if (f > 0) {
            const metrics::PopCounts pops = metrics::count_pops(previous, *frame.flags);
            most = std::max(most, pops.in + pops.out);
        }
        previous = *frame.flags;
        if (all) all->push_back(*frame.flags);
    }
    return most;
}

/// The shock front over 5 report steps and the band (0.55, 0.65) it carries along: cells enter
/// and leave at every step.
class ShockFront : public ::testing::Test {
protected:
    const grid::CornerPointGrid grid = front_grid();
    const VectorSteps source{shock_front(grid, 5)};
    const grid::PrimaryRange band{0.55f, 0.65f};

    /// Runs every frame of `sequence`; at report steps its flags must be `reference`'s for the
    /// step's values. `check` sees every frame.
    void expect_steps_select_as(CoherentSequence& sequence, const AnimationTimeline& timeline, PrimaryTracker& reference,
                                const std::function<void(std::size_t, const CoherentSequence::Frame&)>& check = {}) {
        for (std::size_t f = 0; f < timeline.frame_count(); ++f) {
            const CoherentSequence::Frame frame = sequence.next();
            if (f % timeline.frames_per_step == 0) {
                EXPECT_EQ(*frame.flags, reference.update(source.values(f / timeline.frames_per_step))) << "frame " << f;
            }
            if (check) check(f, frame);
        }
    }
};

TEST_F(ShockFront, NoneChangesEverythingAtStepBoundaries) {
    const AnimationTimeline timeline{0, 4, 4};
    CoherentSequence sequence(grid, source, timeline, Coherence::none, band, 0.1f);  // none ignores the band
    PrimaryTracker anew(grid, "SWAT", band, 0.0f);
    expect_steps_select_as(sequence, timeline, anew, [&](std::size_t f, const CoherentSequence::Frame& frame) {
        EXPECT_EQ(*frame.values, source.values(f / 4)) << "frame " << f;
        EXPECT_EQ(frame.values_changed, f % 4 == 0) << "frame " << f;
    });
    EXPECT_THROW(sequence.next(), std::logic_error);
}

TEST_F(ShockFront, SmoothSpreadsEachStepsChangesOverItsFrames) {
    const std::size_t per_step = 4;
    const AnimationTimeline timeline{0, 4, per_step};
    CoherentSequence none(grid, source, timeline, Coherence::none, band, 0.0f);
    CoherentSequence smooth(grid, source, timeline, Coherence::smooth, band, 0.0f);
    const std::size_t reads_before = source.reads();
    std::vector<std::vector<std::uint8_t>> none_flags, smooth_flags;
    const std::size_t none_max = pop_max(none, timeline.frame_count(), &none_flags);
    const std::size_t smooth_max = pop_max(smooth, timeline.frame_count(), &smooth_flags);
    // Every step is read once by each sequence.
    EXPECT_EQ(source.reads() - reads_before, 10u);
    // Report steps select the same primaries (no band): smooth differs only between them.
    for (std::size_t f = 0; f < timeline.frame_count(); f += per_step) EXPECT_EQ(none_flags[f], smooth_flags[f]) << f;
    // Each step's n changes come one frame in four: at most ceil(n / 4) per frame. Linear
    // interpolation alone would let them all cross within one frame (each swept cell goes from
    // 0.15 to 0.55-0.75 in a step and crosses 0.55 past 3/4 of it).
    EXPECT_GT(none_max, 0u);
    EXPECT_LE(smooth_max, (none_max + per_step - 1) / per_step);
}

TEST_F(ShockFront, FramesCountTheirPrimariesAndOnlySmoothOpensCellsCutsBeforeTheyEnter) {
    // A band the front reaches only after step 1: the primaries appear during the animation.
    const grid::PrimaryRange late{0.75f, 0.8f};
    const AnimationTimeline timeline{0, 4, 4};
    CoherentSequence none(grid, source, timeline, Coherence::none, late, 0.0f);
    CoherentSequence smooth(grid, source, timeline, Coherence::smooth, late, 0.0f);
    const std::size_t opening_frames = frames_to_open(4);  // 8: opening over the 7 frames before entry
    std::vector<std::vector<float>> opening;             // per frame, per cell
    std::vector<std::vector<std::uint8_t>> flags;        // per frame, smooth's
    for (std::size_t f = 0; f < timeline.frame_count(); ++f) {
        const CoherentSequence::Frame n = none.next(), s = smooth.next();
        EXPECT_EQ(n.primary_cells, metrics::count_pops(std::vector<std::uint8_t>(n.flags->size(), 0), *n.flags).in) << f;
        EXPECT_TRUE(n.openings->empty()) << f;
        EXPECT_EQ(s.primary_cells, grid::count_primaries(*s.flags)) << f;
        opening.emplace_back(s.flags->size(), 0.0f);
        for (const OpeningCell& cell : *s.openings) {
            EXPECT_EQ((*s.flags)[cell.cell], 0) << f;
            opening.back()[cell.cell] = cell.opening;
        }
        flags.push_back(*s.flags);
    }
    // Each cell that enters at frame f had its cut opening, wider frame by frame, in the frames
    // f - 7 .. f - 1: it is drawn the frame its cut is open, not later.
    std::size_t entries = 0;
    for (std::size_t f = opening_frames; f < flags.size(); ++f)
        for (std::size_t c = 0; c < flags[f].size(); ++c) {
            if (!flags[f][c] || flags[f - 1][c]) continue;
            ++entries;
            EXPECT_EQ(opening[f - opening_frames][c], 0.0f) << "frame " << f << " cell " << c;
            for (std::size_t k = f - opening_frames + 1; k < f; ++k)
                EXPECT_GT(opening[k][c], opening[k - 1][c]) << "frame " << k << " cell " << c;
        }
    EXPECT_GT(entries, 0u);
}

TEST_F(ShockFront, SmoothHysteresisKeepsPrimariesTheBandCovers) {
    const AnimationTimeline timeline{0, 4, 2};
    CoherentSequence smooth(grid, source, timeline, Coherence::smooth, band, 0.1f);
    PrimaryTracker kept(grid, "SWAT", band, 0.1f);
    expect_steps_select_as(smooth, timeline, kept);
}

TEST(PopReversals, SmoothsHysteresisStopsValuesHoveringAtTheLimitFromPoppingInAndOut) {
    // Every cell's value crosses the primary range's lower limit (0.5) at each report step, by
    // 0.02 either way: the paper's "cells may arbitrary pop in and out". None selects anew and
    // turns every cell back at every step after the first change; smooth's band (0.05 of the
    // colour span 0-1, larger than the 0.02 swing) keeps a cell once it entered.
    const grid::CornerPointGrid grid = front_grid();
    std::vector<std::vector<float>> steps;
    for (int step = 0; step < 6; ++step) steps.emplace_back(grid.cell_count(), step % 2 ? 0.52f : 0.48f);
    const VectorSteps source{steps};
    const AnimationTimeline timeline{0, 5, 4};
    std::size_t reversals[2] = {0, 0};
    for (const Coherence mode : {Coherence::none, Coherence::smooth}) {
        CoherentSequence sequence(grid, source, timeline, mode, {0.5f, 1.0f}, 0.05f);
        metrics::PopReversals counter(grid.cell_count());
        std::vector<std::uint8_t> previous;
        for (std::size_t f = 0; f < timeline.frame_count(); ++f) {
            const CoherentSequence::Frame frame = sequence.next();
            if (f > 0) reversals[mode == Coherence::smooth] += counter.count(previous, *frame.flags);
            previous = *frame.flags;
        }
    }
    EXPECT_EQ(reversals[0], 4 * grid.cell_count());  // in at 1, out at 2, in at 3, out at 4, in at 5
    EXPECT_EQ(reversals[1], 0u);
}

}  // namespace
}  // namespace cutaway::temporal

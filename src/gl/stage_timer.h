#pragma once
// Per-stage GPU timing. On llvmpipe GL timer queries do not measure draws (they time roughly the
// last 64x64 tile), so the time that counts is a fenced wall clock: glFinish before and after the
// stage, std::chrono::steady_clock between. The GL_TIME_ELAPSED query runs beside it and is kept
// with a flag saying whether it agrees with the wall clock.
#include <chrono>
#include <string>
#include <vector>

#include "gl/debug_group.h"
#include "gl/gl_objects.h"

namespace cutaway::gl {

struct StageTime {
    std::string stage;
    double wall_ms = 0;      ///< fenced wall-clock time, milliseconds
    double gl_query_ms = 0;  ///< GL_TIME_ELAPSED of the same commands, milliseconds
    /// Whether the query agrees with the wall clock: query >= 50% of wall time, or within 0.5 ms of
    /// it (the wall clock also counts driver submission, so a real GPU reads somewhat lower), and
    /// not longer than the wall time (at most 10% + 0.5 ms more: the two clocks' granularity).
    bool gl_query_valid = false;
};

/// Whether a GL query time is believable next to the fenced wall time of the same stage.
bool query_agrees(double wall_ms, double query_ms);

class StageTimer {
public:
    /// Starts timing `stage` after a glFinish. Stages do not nest.
    void begin(std::string stage);
    /// glFinish, then records the stage.
    void end();
    const std::vector<StageTime>& stages() const { return stages_; }
    /// Wall time of a recorded stage (0 if it did not run).
    double wall_ms(const std::string& stage) const;
    void clear() { stages_.clear(); }
    /// Off: stages are named but not fenced or timed (wall_ms 0), so a frame runs as a user's
    /// frame would, overlapping its stages; time it as a whole instead.
    void set_fenced(bool fenced) { fenced_ = fenced; }
    bool fenced() const { return fenced_; }

private:
    bool fenced_ = true;
    Query query_;
    std::string current_;
    std::chrono::steady_clock::time_point started_;
    std::vector<StageTime> stages_;
};

/// Runs `work` as one timed stage of `timer`, in a GL debug group of the stage's name.
template <typename Work>
void timed_stage(StageTimer& timer, std::string stage, Work&& work) {
    const DebugGroup group(stage.c_str());
    timer.begin(std::move(stage));
    work();
    timer.end();
}

}  // namespace cutaway::gl

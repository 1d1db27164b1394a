#pragma once
// Plays a viewer script over the frames of the viewer loop: steps run in order at the start of a
// frame until a `wait N` (N frames are drawn, then the next step runs), a `sleep S` (resume after S seconds of wall
// clock) or a step that asks to end the frame (a screenshot, taken once the frame is drawn).
#include <chrono>
#include <functional>

#include "viewer/viewer_script.h"

namespace cutaway::viewer {

class ScriptRunner {
public:
    /// Runs one step; returns true when the frame must be drawn before the next step runs.
    using StepAction = std::function<bool(const ScriptStep&)>;

    explicit ScriptRunner(ViewerScript script);

    /// Runs the steps due at this frame. An exception from `act` is rethrown as
    /// std::invalid_argument prefixed with the step's file and line.
    void run_frame(const StepAction& act);
    bool finished() const { return next_ >= script_.steps.size() && frames_to_wait_ == 0; }
    const ViewerScript& script() const { return script_; }

private:
    ViewerScript script_;
    std::size_t next_ = 0;
    long frames_to_wait_ = 0;
    std::chrono::steady_clock::time_point sleep_until_{};
};

}  // namespace cutaway::viewer

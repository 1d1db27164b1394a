#include "viewer/script_runner.h"

#include <stdexcept>

namespace cutaway::viewer {

ScriptRunner::ScriptRunner(ViewerScript script) : script_(std::move(script)) {}

void ScriptRunner::run_frame(const StepAction& act) {
    if (frames_to_wait_ > 0 && --frames_to_wait_ > 0) return;
    if (std::chrono::steady_clock::now() < sleep_until_) return;
    while (next_ < script_.steps.size()) {
        const ScriptStep& step = script_.steps[next_++];
        if (step.action == "wait") {
            frames_to_wait_ = std::stol(step.args.at(0));
            if (frames_to_wait_ > 0) return;
            continue;
        }
        if (step.action == "sleep") {
            const auto seconds = std::chrono::duration<double>(std::stod(step.args.at(0)));
            sleep_until_ = std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::nanoseconds>(seconds);
            return;
        }
        try {
            if (act(step)) return;
        } catch (const std::exception& error) {
            throw std::invalid_argument(describe(script_, step) + ": " + error.what());
        }
    }
}

}  // namespace cutaway::viewer

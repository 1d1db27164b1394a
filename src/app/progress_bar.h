#pragma once
// A one-line progress bar ("animate [########------] 12/40 frames") redrawn in place on stderr,
// only when stderr is a terminal: logs and pipes get nothing.
#include <cstddef>
#include <string>

namespace cutaway::app {

class ProgressBar {
public:
    /// `label`: what runs (e.g. "cutaway animate"); `total`: steps to the end; `unit`: what a step is.
    ProgressBar(std::string label, std::size_t total, std::string unit);
    /// Ends the line if anything was drawn.
    ~ProgressBar();
    ProgressBar(const ProgressBar&) = delete;
    ProgressBar& operator=(const ProgressBar&) = delete;

    /// Redraws the bar with `done` of the total finished.
    void show(std::size_t done);
    bool visible() const { return on_terminal_; }

private:
    std::string label_;
    std::size_t total_;
    std::string unit_;
    bool on_terminal_;
    bool drawn_ = false;
};

}  // namespace cutaway::app

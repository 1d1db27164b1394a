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
    /// end().
    ~ProgressBar() { end(); }
    ProgressBar(const ProgressBar&) = delete;
    ProgressBar& operator=(const ProgressBar&) = delete;

    /// Redraws the bar with `done` of the total finished.
    void show(std::size_t done);
    /// Ends the bar's line if anything was drawn (before other output); show() starts a new one.
    void end();
    bool visible() const { return on_terminal_; }

private:
    std::string label_;
    std::size_t total_;
    std::string unit_;
    bool on_terminal_;
    bool drawn_ = false;
};

}  // namespace cutaway::app

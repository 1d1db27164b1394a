#include "app/progress_bar.h"

#include <unistd.h>

#include <algorithm>
#include <iostream>
#include <utility>

namespace cutaway::app {

/// Characters of the bar itself: fits an 80-column terminal with the label and the count.
constexpr std::size_t bar_width = 30;

ProgressBar::ProgressBar(std::string label, std::size_t total, std::string unit)
    : label_(std::move(label)), total_(std::max<std::size_t>(total, 1)), unit_(std::move(unit)),
      on_terminal_(::isatty(STDERR_FILENO) == 1) {}

void ProgressBar::end() {
    if (drawn_) std::cerr << '\n' << std::flush;
    drawn_ = false;
}

void ProgressBar::show(std::size_t done) {
    if (!on_terminal_) return;
    const std::size_t filled = std::min(done, total_) * bar_width / total_;
    std::cerr << '\r' << label_ << " [" << std::string(filled, '#') << std::string(bar_width - filled, '-') << "] "
              << done << '/' << total_ << ' ' << unit_ << std::flush;
    drawn_ = true;
}

}  // namespace cutaway::app

#pragma once
// Stage-by-stage progress lines ("generate: horizons 1.23 s (total 2.50 s)") on a stream, or
// nothing when the stream is null.
#include <chrono>
#include <ostream>
#include <string>

namespace cutaway::generators {

class ProgressLog {
public:
    explicit ProgressLog(std::ostream* out) : out_(out), start_(clock::now()), last_(start_) {}

    /// Reports that `stage` just finished, with its duration and the time since construction.
    void finished(const std::string& stage, const std::string& detail = {});
    double total_seconds() const;

private:
    using clock = std::chrono::steady_clock;
    std::ostream* out_;
    clock::time_point start_;
    clock::time_point last_;
};

}  // namespace cutaway::generators

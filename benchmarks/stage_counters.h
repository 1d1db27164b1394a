#pragma once
// Per-stage frame times as Google Benchmark counters, two clocks side by side: `<stage>` the fenced
// wall time (glFinish before and after) and `gpu_ms_<stage>` the GL_TIME_ELAPSED timer query of
// the same commands, each the median over the timed frames in milliseconds, plus `gpu_query_valid`
// (1 when every query of every timed frame agreed with its wall clock, gl::query_agrees). On a
// software rasteriser the queries mostly disagree (SPEC.md section 5): the fenced times are the
// measurement there, the queries the GPU's own count where it keeps one.
#include <map>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "gl/stage_timer.h"

namespace cutaway::bench {

/// One frame's times summed by stage name (a stage may be recorded in several parts), ms.
struct FrameStageTimes {
    std::map<std::string, double> wall_ms;
    std::map<std::string, double> gpu_ms;
    bool queries_valid = true;
};

/// `stages` summed by name over the stages named in `names` (others left out: every MPI rank then
/// holds the same names); each name present, 0 when the stage did not run this frame.
template <typename Names>
FrameStageTimes sum_by_stage(const Names& names, const std::vector<gl::StageTime>& stages) {
    FrameStageTimes frame;
    for (const auto& name : names) frame.wall_ms[name] = frame.gpu_ms[name] = 0.0;
    for (const gl::StageTime& stage : stages) {
        if (frame.wall_ms.count(stage.stage) == 0) continue;
        frame.wall_ms[stage.stage] += stage.wall_ms;
        frame.gpu_ms[stage.stage] += stage.gl_query_ms;
        frame.queries_valid = frame.queries_valid && stage.gl_query_valid;
    }
    return frame;
}

/// The timed frames' stage times, one entry per frame and stage.
class StageCounters {
public:
    void add(const FrameStageTimes& frame);
    /// Median fenced wall time of `stage` over the frames, ms (0 if never recorded).
    double median_wall_ms(const std::string& stage) const;
    /// Sets `<stage>`, `gpu_ms_<stage>` and `gpu_query_valid` on `state`.
    void set_counters(benchmark::State& state) const;

private:
    std::map<std::string, std::vector<double>> wall_ms_;
    std::map<std::string, std::vector<double>> gpu_ms_;
    bool queries_valid_ = true;
};

}  // namespace cutaway::bench

#include "stage_counters.h"

#include "metrics/median.h"

namespace cutaway::bench {

void StageCounters::add(const FrameStageTimes& frame) {
    for (const auto& [stage, ms] : frame.wall_ms) wall_ms_[stage].push_back(ms);
    for (const auto& [stage, ms] : frame.gpu_ms) gpu_ms_[stage].push_back(ms);
    queries_valid_ = queries_valid_ && frame.queries_valid;
}

double StageCounters::median_wall_ms(const std::string& stage) const {
    const auto found = wall_ms_.find(stage);
    return found == wall_ms_.end() ? 0.0 : metrics::median(found->second);
}

void StageCounters::set_counters(benchmark::State& state) const {
    for (const auto& [stage, times] : wall_ms_) state.counters[stage] = metrics::median(times);
    for (const auto& [stage, times] : gpu_ms_) state.counters["gpu_ms_" + stage] = metrics::median(times);
    state.counters["gpu_query_valid"] = queries_valid_ && !wall_ms_.empty() ? 1 : 0;
}

}  // namespace cutaway::bench

#include "gl/stage_timer.h"

#include <algorithm>

#include "gl/gl_error.h"

namespace cutaway::gl {

bool query_agrees(double wall_ms, double query_ms) {
    const bool not_too_short = query_ms >= 0.5 * wall_ms || wall_ms - query_ms < 0.5;
    // The query's commands run between the two glFinish calls that bound the wall time, so it
    // cannot be longer; 10% and 0.5 ms allow for the two clocks' granularity. llvmpipe has
    // returned absurd values, far longer than the stage (scale-10m, frustum-sweep).
    const bool not_too_long = query_ms <= 1.1 * wall_ms + 0.5;
    return not_too_short && not_too_long;
}

void StageTimer::begin(std::string stage) {
    if (!current_.empty()) throw GlError("stage timer: '" + stage + "' begun inside '" + current_ + "'");
    current_ = std::move(stage);
    if (!fenced_) return;
    if (!query_) query_ = Query(GL_TIME_ELAPSED);
    glFinish();
    started_ = std::chrono::steady_clock::now();
    glBeginQuery(GL_TIME_ELAPSED, query_.id());
}

void StageTimer::end() {
    if (!fenced_) {
        stages_.push_back({std::move(current_), 0.0, 0.0, false});
        current_.clear();
        return;
    }
    glEndQuery(GL_TIME_ELAPSED);
    glFinish();
    const auto stopped = std::chrono::steady_clock::now();
    GLuint64 elapsed_ns = 0;
    glGetQueryObjectui64v(query_.id(), GL_QUERY_RESULT, &elapsed_ns);
    StageTime time;
    time.stage = std::move(current_);
    current_.clear();
    time.wall_ms = std::chrono::duration<double, std::milli>(stopped - started_).count();
    time.gl_query_ms = double(elapsed_ns) * 1e-6;
    time.gl_query_valid = query_agrees(time.wall_ms, time.gl_query_ms);
    stages_.push_back(std::move(time));
}

double StageTimer::wall_ms(const std::string& stage) const {
    double total = 0;
    for (const StageTime& time : stages_)
        if (time.stage == stage) total += time.wall_ms;
    return total;
}

}  // namespace cutaway::gl

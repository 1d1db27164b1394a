#include "progress_log.h"

#include <cstdio>

namespace cutaway::generators {

void ProgressLog::finished(const std::string& stage, const std::string& detail) {
    const clock::time_point now = clock::now();
    if (out_) {
        char times[64];
        std::snprintf(times, sizeof times, "%.2f s (total %.2f s)", std::chrono::duration<double>(now - last_).count(),
                      std::chrono::duration<double>(now - start_).count());
        *out_ << "generate: " << stage << ' ' << times << (detail.empty() ? "" : ": ") << detail << std::endl;
    }
    last_ = now;
}

double ProgressLog::total_seconds() const { return std::chrono::duration<double>(clock::now() - start_).count(); }

}  // namespace cutaway::generators

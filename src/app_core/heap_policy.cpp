#include "app_core/heap_policy.h"

#include <malloc.h>

namespace cutaway::app {

bool keep_freed_heap_memory() { return mallopt(M_TRIM_THRESHOLD, int(kept_free_heap_bytes)) == 1; }

nlohmann::json heap_trim_threshold_json() {
    return keep_freed_heap_memory() ? nlohmann::json(kept_free_heap_bytes) : nlohmann::json(nullptr);
}

}  // namespace cutaway::app

#include "app_core/run_context_json.h"

#include "app_core/heap_policy.h"
#include "app_core/run_context.h"
#include "gl/gl_context.h"

namespace cutaway::app {

GlDevice current_gl_device(const std::string& platform) { return {gl::gl_renderer(), gl::gl_version(), platform}; }

nlohmann::json run_context_json(const GlDevice& device) {
    nlohmann::json context{{"gl_renderer", device.renderer},
                           {"lp_num_threads", run_context::lp_num_threads()},
                           {"heap_trim_threshold_bytes", heap_trim_threshold_json()},
                           {"git_revision", run_context::git_revision()}};
    if (!device.version.empty()) context["gl_version"] = device.version;
    if (!device.platform.empty()) context["gl_platform"] = device.platform;
    return context;
}

}  // namespace cutaway::app

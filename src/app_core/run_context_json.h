#pragma once
// The machine and build context every stats.json records beside its numbers, written in one place:
// the GL device, llvmpipe's thread count, the heap policy and the git revision.
#include <nlohmann/json.hpp>
#include <string>

namespace cutaway::app {

struct GlDevice {
    std::string renderer;  ///< GL_RENDERER, or what drew instead (the CPU caster)
    std::string version;   ///< GL_VERSION (empty: none)
    std::string platform;  ///< the EGL platform or window system (empty: none)
};

/// GL_RENDERER, GL_VERSION of the current context, with `platform`.
GlDevice current_gl_device(const std::string& platform);

/// {gl_renderer, gl_version, gl_platform, lp_num_threads, heap_trim_threshold_bytes, git_revision}
/// (the GL fields only where known), merged into a stats object with update().
nlohmann::json run_context_json(const GlDevice& device);

}  // namespace cutaway::app

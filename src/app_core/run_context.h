#pragma once
// Machine and build context every run records (benchmarks, render stats): git revision, uname, environment.
#include <sys/utsname.h>

#include <array>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

namespace cutaway::run_context {

/// First line printed by `command` (empty if it fails or prints nothing).
inline std::string command_line_output(const std::string& command) {
    std::string out;
    if (FILE* pipe = ::popen(command.c_str(), "r")) {
        std::array<char, 256> buffer{};
        while (std::fgets(buffer.data(), int(buffer.size()), pipe)) out += buffer.data();
        ::pclose(pipe);
    }
    const auto end = out.find('\n');
    return end == std::string::npos ? out : out.substr(0, end);
}

/// CUTAWAY_GIT_REVISION from the environment, else `git rev-parse HEAD` in the source tree
/// (with "-dirty" when tracked files outside results/ and paper_figures/ differ from HEAD: an experiment
/// rewrites its outputs there as it goes, and a later run of the same experiment must not read
/// them as a changed source), else "unknown".
inline std::string git_revision() {
    if (const char* env = std::getenv("CUTAWAY_GIT_REVISION"); env && *env) return env;
#ifdef CUTAWAY_SOURCE_DIR
    const std::string git = "git -C '" + std::string(CUTAWAY_SOURCE_DIR) + "' ";
    const std::string head = command_line_output(git + "rev-parse HEAD 2>/dev/null");
    if (head.empty()) return "unknown";
    const std::string dirty = command_line_output(git + "status --porcelain --untracked-files=no -- . ':!results' ':!paper_figures' 2>/dev/null");
    return dirty.empty() ? head : head + "-dirty";
#else
    return "unknown";
#endif
}

/// `uname -srvm` equivalent.
inline std::string uname_text() {
    struct utsname u {};
    if (::uname(&u) != 0) return "unknown";
    return std::string(u.sysname) + " " + u.release + " " + u.version + " " + u.machine;
}

/// Value of an environment variable, or empty.
inline std::string env_or_empty(const char* name) {
    const char* value = std::getenv(name);
    return value ? value : "";
}


/// LP_NUM_THREADS as set for llvmpipe, or "unset" (llvmpipe then uses one thread per core).
inline std::string lp_num_threads() {
    const std::string value = env_or_empty("LP_NUM_THREADS");
    return value.empty() ? "unset" : value;
}

/// A memory field of /proc/self/status in bytes (VmHWM: peak resident, VmRSS: resident now); 0 if absent.
inline std::size_t proc_status_bytes(const std::string& field) {
    std::ifstream status("/proc/self/status");
    for (std::string line; std::getline(status, line);)
        if (line.rfind(field + ":", 0) == 0) {
            std::istringstream in(line.substr(field.size() + 1));
            std::size_t kb = 0;
            in >> kb;
            return kb * 1024;
        }
    return 0;
}

}  // namespace cutaway::run_context


#pragma once
// Machine and build context every run records (benchmarks, render stats): git revision, uname, environment.
#include <sys/resource.h>
#include <sys/utsname.h>
#include <unistd.h>

#include <array>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
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
/// (with "-dirty" when tracked files outside results/ differ from HEAD: a run rewrites results/), else "unknown".
inline std::string git_revision() {
    if (const char* env = std::getenv("CUTAWAY_GIT_REVISION"); env && *env) return env;
#ifdef CUTAWAY_SOURCE_DIR
    const std::string git = "git -C '" + std::string(CUTAWAY_SOURCE_DIR) + "' ";
    const std::string head = command_line_output(git + "rev-parse HEAD 2>/dev/null");
    if (head.empty()) return "unknown";
    const std::string dirty = command_line_output(git + "status --porcelain --untracked-files=no -- . ':!results' 2>/dev/null");
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

}  // namespace cutaway::run_context

namespace cutaway::run_context {

/// LP_NUM_THREADS as set for llvmpipe, or "unset" (llvmpipe then uses one thread per core).
inline std::string lp_num_threads() {
    const std::string value = env_or_empty("LP_NUM_THREADS");
    return value.empty() ? "unset" : value;
}

}  // namespace cutaway::run_context

namespace cutaway::run_context {

/// The largest resident set this process has had so far (getrusage's ru_maxrss, KiB on Linux), bytes.
inline std::size_t peak_resident_bytes() {
    struct rusage usage {};
    return ::getrusage(RUSAGE_SELF, &usage) == 0 ? std::size_t(usage.ru_maxrss) * 1024 : 0;
}

/// The resident set now (second field of /proc/self/statm, in pages), bytes; 0 where unavailable.
inline std::size_t resident_bytes() {
    std::size_t pages_total = 0, pages_resident = 0;
    FILE* statm = std::fopen("/proc/self/statm", "r");
    if (!statm) return 0;
    const bool read = std::fscanf(statm, "%zu %zu", &pages_total, &pages_resident) == 2;
    std::fclose(statm);
    return read ? pages_resident * std::size_t(::sysconf(_SC_PAGESIZE)) : 0;
}

}  // namespace cutaway::run_context

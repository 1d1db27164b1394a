#pragma once
// Runs the `cutaway` program as a user would, in a child process: exit code, stdout, stderr and
// the child's peak resident memory (wait4's rusage), with an optional file-size limit so a write
// can be made to fail half-way.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace cutaway::testing {

struct ProcessResult {
    int exit_code = -1;        ///< -1 when the child was killed by a signal
    int signal = 0;
    bool interrupted = false;  ///< ProcessLimits::interrupt_signal was sent
    std::string out;
    std::string err;
    double peak_rss_mb = 0;    ///< ru_maxrss of the child, MiB
    double seconds = 0;        ///< wall time
};

struct ProcessLimits {
    /// RLIMIT_FSIZE for the child (0: none): writes past it fail with EFBIG (SIGXFSZ is ignored).
    std::size_t max_file_bytes = 0;
    /// When not 0: sent to the child as soon as a file whose name holds `interrupt_when_named`
    /// appears in `interrupt_watch` (the moment a staged output starts), as a user's Ctrl-C or kill.
    int interrupt_signal = 0;
    std::filesystem::path interrupt_watch;
    std::string interrupt_when_named = ".partial-";
};

/// Runs `program args...` with its output captured under `scratch`.
ProcessResult run_process(const std::string& program, const std::vector<std::string>& args,
                          const std::filesystem::path& scratch, ProcessLimits limits = {});

}  // namespace cutaway::testing

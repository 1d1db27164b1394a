#include "cutaway_process.h"

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>

namespace cutaway::testing {
namespace {

std::string read_all(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

/// Whether a file of `directory` has `fragment` in its name.
bool watched_file_exists(const std::filesystem::path& directory, const std::string& fragment) {
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(directory, error))
        if (entry.path().filename().string().find(fragment) != std::string::npos) return true;
    return false;
}

}  // namespace

ProcessResult run_process(const std::string& program, const std::vector<std::string>& args,
                          const std::filesystem::path& scratch, ProcessLimits limits) {
    const std::filesystem::path out_path = scratch / "child.stdout", err_path = scratch / "child.stderr";
    std::vector<std::string> argv_text{program};
    argv_text.insert(argv_text.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& a : argv_text) argv.push_back(a.data());
    argv.push_back(nullptr);

    const auto started = std::chrono::steady_clock::now();
    const pid_t pid = ::fork();
    if (pid < 0) throw std::runtime_error("fork failed");
    if (pid == 0) {
        const int out = ::open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int err = ::open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (out < 0 || err < 0) ::_exit(126);
        ::dup2(out, 1);
        ::dup2(err, 2);
        if (limits.max_file_bytes > 0) {
            std::signal(SIGXFSZ, SIG_IGN);  // stays ignored across exec: the write fails with EFBIG instead
            const rlimit size{limits.max_file_bytes, limits.max_file_bytes};
            ::setrlimit(RLIMIT_FSIZE, &size);
        }
        ::execv(program.c_str(), argv.data());
        ::_exit(127);
    }
    int status = 0;
    rusage usage{};
    ProcessResult result;
    if (limits.interrupt_signal != 0) {
        // Polls for the watched file while the child runs (every millisecond: a staged output of a
        // small run lives for a few milliseconds only).
        while (true) {
            const pid_t done = ::wait4(pid, &status, WNOHANG, &usage);
            if (done == pid) break;
            if (done < 0) throw std::runtime_error("wait4 failed");
            if (!result.interrupted && watched_file_exists(limits.interrupt_watch, limits.interrupt_when_named)) {
                ::kill(pid, limits.interrupt_signal);
                result.interrupted = true;
            }
            ::usleep(1000);
        }
    } else if (::wait4(pid, &status, 0, &usage) != pid) {
        throw std::runtime_error("wait4 failed");
    }
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    if (WIFEXITED(status)) result.exit_code = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) result.signal = WTERMSIG(status);
    result.peak_rss_mb = double(usage.ru_maxrss) / 1024.0;  // Linux reports KiB
    result.out = read_all(out_path);
    result.err = read_all(err_path);
    std::filesystem::remove(out_path);
    std::filesystem::remove(err_path);
    return result;
}

}  // namespace cutaway::testing

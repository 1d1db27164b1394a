#include "io/staged_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "io/interrupt_cleanup.h"
#include "io/output_error.h"
#include "io/path_text.h"

namespace cutaway::io {
namespace {

/// True when `path` names an existing file that is not a regular file (device, FIFO, socket).
bool is_special_file(const std::filesystem::path& path) {
    struct stat status {};
    return ::stat(path.c_str(), &status) == 0 && !S_ISREG(status.st_mode) && !S_ISDIR(status.st_mode);
}

}  // namespace

void fail_output(const std::filesystem::path& path, int error_number) {
    const std::string reason = error_number != 0 ? std::strerror(error_number) : "unknown reason";
    throw OutputError(shown_path(path) + ": expected the output written whole, found an error: " + reason);
}

StagedFile::StagedFile(std::filesystem::path target) : target_(std::move(target)) {
    if (target_.empty()) throw OutputError("output path: expected a file name, found an empty path");
    if (is_special_file(target_)) {
        in_place_ = true;
        write_path_ = target_;
        return;
    }
    const std::filesystem::path directory = target_.has_parent_path() ? target_.parent_path() : ".";
    // Appended piece by piece: GCC 12 reports a false -Wrestrict on "literal" + std::string.
    std::string hidden_name(".");
    hidden_name.append(target_.filename().string()).append(".partial-XXXXXX");
    const std::string name = (directory / hidden_name).string();
    std::vector<char> buffer(name.begin(), name.end());
    buffer.push_back('\0');
    const int fd = create_interrupt_file(buffer.data(), interrupt_slot_);
    if (fd == interrupt_table_full)
        throw OutputError(shown_path(target_) + ": expected at most " + std::to_string(max_interrupt_files) +
                          " outputs staged at once, found more");
    if (fd < 0) fail_output(target_, errno);
    // mkstemp makes 0600; an output gets what open(..., 0666) would give under the umask.
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(fd, 0666 & ~mask);
    ::close(fd);
    write_path_ = buffer.data();
}

StagedFile::~StagedFile() {
    if (!in_place_ && !committed_) ::unlink(write_path_.c_str());
    release_interrupt_file(interrupt_slot_);
}

void StagedFile::commit() {
    if (in_place_) return;
    if (::rename(write_path_.c_str(), target_.c_str()) != 0) fail_output(target_, errno);
    committed_ = true;
    release_interrupt_file(std::exchange(interrupt_slot_, -1));
}

std::string output_path_problem(const std::filesystem::path& path) {
    if (path.empty()) return "expected a file name, found an empty path";
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) return "expected a file, found the directory '" + shown_path(path) + "'";
    if (is_special_file(path)) {  // written in place (/dev/null): only the file itself must be writable
        if (::access(path.c_str(), W_OK) == 0) return {};
        return "expected a writable file, found '" + shown_path(path) + "' (" + std::strerror(errno) + ")";
    }
    const std::filesystem::path directory = path.has_parent_path() ? path.parent_path() : ".";
    if (!std::filesystem::is_directory(directory, error)) {
        std::string text("expected a file in an existing directory, found '");
        text.append(shown_path(path)).append("' (");
        if (std::filesystem::exists(directory, error))
            text.append("'").append(shown_path(directory)).append("' is not a directory)");
        else
            text.append("no directory '").append(shown_path(directory)).append("')");
        return text;
    }
    if (::access(directory.c_str(), W_OK | X_OK) != 0)
        return "expected a file in a writable directory, found '" + shown_path(path) + "' (" + std::strerror(errno) + ")";
    if (std::filesystem::exists(path, error) && ::access(path.c_str(), W_OK) != 0)
        return "expected a writable file, found '" + shown_path(path) + "' (" + std::strerror(errno) + ")";
    return {};
}

std::string output_directory_problem(const std::filesystem::path& path) {
    if (path.empty()) return "expected a directory name, found an empty path";
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) {
        if (::access(path.c_str(), W_OK | X_OK) == 0) return {};
        return "expected a writable directory, found '" + path.string() + "' (" + std::strerror(errno) + ")";
    }
    if (std::filesystem::exists(path, error))
        return "expected a directory, found the file '" + path.string() + "'";
    const std::filesystem::path parent = path.has_parent_path() ? path.parent_path() : ".";
    if (!std::filesystem::is_directory(parent, error))
        return "expected a directory that exists or can be made in an existing one, found '" + path.string() +
               "' (no directory '" + parent.string() + "')";
    if (::access(parent.c_str(), W_OK | X_OK) != 0)
        return "expected a directory that can be made, found '" + path.string() + "' ('" + parent.string() +
               "': " + std::strerror(errno) + ")";
    return {};
}

}  // namespace cutaway::io

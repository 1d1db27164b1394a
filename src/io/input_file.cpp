#include "io/input_file.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>

namespace cutaway::io {

std::string input_file_problem(const std::filesystem::path& path) {
    if (path.empty()) return "an empty path";
    struct stat status {};
    if (::stat(path.c_str(), &status) != 0) {
        const int error_number = errno;
        struct stat link {};
        if (error_number == ENOENT && ::lstat(path.c_str(), &link) == 0) return "a symbolic link to a missing file";
        switch (error_number) {
            case ENOENT: return "no such file";
            case ELOOP: return "a loop of symbolic links (ELOOP)";
            case ENAMETOOLONG: return "a name too long for the file system (ENAMETOOLONG)";
            case ENOTDIR: return "a path through a file that is not a directory";
            default: return std::strerror(error_number);
        }
    }
    if (S_ISREG(status.st_mode)) return {};
    if (S_ISDIR(status.st_mode)) return "a directory";
    if (S_ISFIFO(status.st_mode)) return "a FIFO (reading it would wait for a writer)";
    if (S_ISSOCK(status.st_mode)) return "a socket";
    if (S_ISCHR(status.st_mode) || S_ISBLK(status.st_mode)) return "a device";
    return "not a regular file";
}

}  // namespace cutaway::io

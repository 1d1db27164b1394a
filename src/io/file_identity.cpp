#include "io/file_identity.h"

#include <sys/stat.h>

#include <system_error>

#include "io/path_text.h"

namespace cutaway::io {

bool FileIdentity::operator==(const FileIdentity& other) const {
    if (exists != other.exists) return false;
    return exists ? device == other.device && inode == other.inode : would_be == other.would_be;
}

FileIdentity file_identity(const std::filesystem::path& path) {
    FileIdentity identity;
    struct stat status {};
    if (::stat(path.c_str(), &status) == 0) {
        identity.exists = true;
        identity.device = status.st_dev;
        identity.inode = status.st_ino;
        return identity;
    }
    std::error_code error;
    const std::filesystem::path absolute = std::filesystem::absolute(path, error).lexically_normal();
    const std::filesystem::path directory = std::filesystem::canonical(absolute.parent_path(), error);
    identity.would_be = error ? absolute : directory / absolute.filename();
    return identity;
}

std::string overwrite_problem(const std::vector<NamedFile>& inputs, const std::vector<NamedFile>& outputs) {
    std::vector<std::pair<const NamedFile*, FileIdentity>> known;
    for (const NamedFile& input : inputs)
        if (!input.path.empty()) known.emplace_back(&input, file_identity(input.path));
    for (const NamedFile& output : outputs) {
        if (output.path.empty()) continue;
        const FileIdentity identity = file_identity(output.path);
        for (const auto& [earlier, earlier_identity] : known)
            if (identity == earlier_identity) {
                const bool same_text = earlier->path == output.path;
                return output.role + ": expected a file other than " + earlier->role + "'s, found the same file '" +
                       shown_path(output.path) + "'" + (same_text ? "" : " (named '" + shown_path(earlier->path) + "' there)");
            }
        known.emplace_back(&output, identity);
    }
    return {};
}

}  // namespace cutaway::io

#pragma once
// Notices edits under the shader directory so the viewer can reload its programs (hot reload).
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>

namespace cutaway::viewer {

class ShaderWatcher {
public:
    /// Takes a snapshot of every file under `root` (recursive); a missing root directory throws
    /// std::invalid_argument naming it.
    explicit ShaderWatcher(std::filesystem::path root);

    /// True once after any file under root was added, removed, or changed (size or last write time)
    /// since the previous poll or construction. Filesystem errors while scanning (e.g. a file removed
    /// mid-scan) never throw: that poll returns false and the next one retries.
    bool poll();

    const std::filesystem::path& root() const;

private:
    struct FileStamp {
        std::uintmax_t size = 0;
        std::filesystem::file_time_type last_write;
        bool operator==(const FileStamp&) const = default;
    };
    using Snapshot = std::map<std::filesystem::path, FileStamp>;

    /// Every regular file under root_, or nothing when the scan hit a filesystem error.
    std::optional<Snapshot> scan() const;

    std::filesystem::path root_;
    Snapshot snapshot_;
};

}  // namespace cutaway::viewer

#include "viewer/shader_watcher.h"

#include <stdexcept>
#include <system_error>
#include <utility>

namespace fs = std::filesystem;

namespace cutaway::viewer {

ShaderWatcher::ShaderWatcher(fs::path root) : root_(std::move(root)) {
    std::error_code error;
    if (!fs::is_directory(root_, error))
        throw std::invalid_argument("shader directory " + root_.string() + " not found; expected an existing directory");
    snapshot_ = scan().value_or(Snapshot{});
}

bool ShaderWatcher::poll() {
    std::optional<Snapshot> current = scan();
    if (!current) return false;
    const bool changed = *current != snapshot_;
    snapshot_ = std::move(*current);
    return changed;
}

const fs::path& ShaderWatcher::root() const { return root_; }

std::optional<ShaderWatcher::Snapshot> ShaderWatcher::scan() const {
    Snapshot snapshot;
    std::error_code error;
    for (fs::recursive_directory_iterator it(root_, error), end; !error && it != end; it.increment(error)) {
        if (!it->is_regular_file(error)) {
            if (error) return std::nullopt;
            continue;
        }
        FileStamp stamp;
        stamp.size = it->file_size(error);
        if (!error) stamp.last_write = it->last_write_time(error);
        if (error) return std::nullopt;
        snapshot.emplace(it->path(), stamp);
    }
    if (error) return std::nullopt;
    return snapshot;
}

}  // namespace cutaway::viewer

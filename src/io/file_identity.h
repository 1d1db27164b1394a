#pragma once
// Which file a path names, whatever the spelling: `out.png`, `./out.png`, `/abs/dir/out.png` and a
// symbolic link to it are one file. Outputs are compared with each other and with every input by
// this identity before any work, so that no output overwrites an input or another output.
#include <sys/types.h>

#include <filesystem>
#include <string>
#include <vector>

namespace cutaway::io {

/// An existing file is its device and inode (hard links and symbolic links resolve to it); a file
/// that does not exist yet is its directory's canonical path plus its name (the file it would become).
struct FileIdentity {
    bool exists = false;
    dev_t device = 0;
    ino_t inode = 0;
    std::filesystem::path would_be;  ///< canonical directory / name, for a file that does not exist

    bool operator==(const FileIdentity& other) const;
    bool operator!=(const FileIdentity& other) const { return !(*this == other); }
};

/// The identity of `path`. A directory that cannot be resolved (missing, no permission) leaves the
/// path made absolute and normalised lexically: two spellings of it still compare equal.
FileIdentity file_identity(const std::filesystem::path& path);

/// A file a command reads or writes, with the option (or role) that named it: "--out", "the model".
struct NamedFile {
    std::string role;
    std::string path;
};

/// Why one of `outputs` would overwrite an input or another output ("--cell-ids: expected a file
/// other than --out's, found the same file ..."), or empty when they are all distinct. Empty paths
/// are skipped (an option not given); inputs may name one file several times.
std::string overwrite_problem(const std::vector<NamedFile>& inputs, const std::vector<NamedFile>& outputs);

}  // namespace cutaway::io

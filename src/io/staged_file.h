#pragma once
// Output files written under a temporary name in the target's directory and renamed onto the
// target only when every write succeeded, so a failed run never leaves a partial file; the
// temporary file is registered for removal on SIGINT/SIGTERM (interrupt_cleanup.h). Targets that
// are not regular files (/dev/null, /dev/full, a FIFO) are written in place: renaming onto them
// would replace the device node. Several outputs of one run are committed together by an
// OutputBatch (output_batch.h).
#include <filesystem>
#include <string>

namespace cutaway::io {

class StagedFile {
public:
    /// Creates the temporary file beside `target`; throws OutputError naming `target` and the reason.
    explicit StagedFile(std::filesystem::path target);
    /// Removes the temporary file unless commit() succeeded.
    ~StagedFile();
    StagedFile(const StagedFile&) = delete;
    StagedFile& operator=(const StagedFile&) = delete;

    /// Where the writer writes: the temporary file, or the target itself for a special file.
    const std::filesystem::path& write_path() const { return write_path_; }
    const std::filesystem::path& target() const { return target_; }
    /// Renames the temporary file onto the target; throws OutputError on failure.
    void commit();

private:
    std::filesystem::path target_;
    std::filesystem::path write_path_;
    bool in_place_ = false;
    bool committed_ = false;
    int interrupt_slot_ = -1;  ///< register_interrupt_file's slot of the temporary file
};

/// Throws OutputError "PATH: expected the output written whole, found an error: REASON" with
/// REASON from errno (or "unknown reason").
[[noreturn]] void fail_output(const std::filesystem::path& path, int error_number);

/// Why `path` cannot take an output ("expected ..., found ..."), or empty when it can: checked
/// before any work so that a run never computes a result it cannot keep.
std::string output_path_problem(const std::filesystem::path& path);

/// Why `path` cannot take output files ("expected ..., found ..."), or empty when it can: a
/// writable directory, or a missing one whose parent is a writable directory (it is created).
std::string output_directory_problem(const std::filesystem::path& path);

}  // namespace cutaway::io

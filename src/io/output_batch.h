#pragma once
// The outputs of one run, committed together: each is written whole under a temporary name as
// soon as it is ready (StagedFile), and commit() renames them onto their targets only after every
// one was written. A run that fails on its last output (a full disk under --stats) or is
// interrupted leaves none of them behind, and no temporary file either.
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <memory>
#include <string_view>
#include <vector>

#include "io/staged_file.h"

namespace cutaway::io {

class OutputBatch {
public:
    OutputBatch() = default;
    /// Removes every temporary file not yet committed.
    ~OutputBatch();
    OutputBatch(const OutputBatch&) = delete;
    OutputBatch& operator=(const OutputBatch&) = delete;

    /// Writes `bytes` whole to a temporary file for `target`, checking every write and the close;
    /// throws OutputError naming `target` and the reason.
    void write(const std::filesystem::path& target, std::string_view bytes);
    /// Lets `fill` write `target`'s temporary file as a stream, then checks the flush and close.
    void write_stream(const std::filesystem::path& target, const std::function<void(std::ostream&)>& fill);
    /// Renames every written file onto its target, in the order written; a signal meanwhile is
    /// handled after the last rename. (A rename that fails half-way, which needs the directory
    /// to change under the run, leaves the earlier ones in place.)
    void commit();

private:
    std::vector<std::unique_ptr<StagedFile>> staged_;
};

/// One output written whole and committed at once (an OutputBatch of one file).
void write_file(const std::filesystem::path& path, std::string_view bytes);
/// One output written as a stream and committed at once.
void write_stream(const std::filesystem::path& path, const std::function<void(std::ostream&)>& fill);

}  // namespace cutaway::io

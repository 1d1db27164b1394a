#include "io/output_batch.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <fstream>

#include "io/interrupt_cleanup.h"

namespace cutaway::io {

OutputBatch::~OutputBatch() = default;  // each StagedFile removes its uncommitted temporary file

void OutputBatch::write(const std::filesystem::path& target, std::string_view bytes) {
    auto staged = std::make_unique<StagedFile>(target);
    const int fd = ::open(staged->write_path().c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
    if (fd < 0) fail_output(target, errno);
    std::size_t written = 0;
    while (written < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            const int error_number = n < 0 ? errno : ENOSPC;
            ::close(fd);
            fail_output(target, error_number);
        }
        written += std::size_t(n);
    }
    if (::close(fd) != 0) fail_output(target, errno);
    staged_.push_back(std::move(staged));
}

void OutputBatch::write_stream(const std::filesystem::path& target, const std::function<void(std::ostream&)>& fill) {
    auto staged = std::make_unique<StagedFile>(target);
    std::ofstream out(staged->write_path(), std::ios::binary | std::ios::trunc);
    if (!out) fail_output(target, errno);
    fill(out);
    if (!out) fail_output(target, errno);  // a write failed: its errno is still the last one set
    errno = 0;
    out.flush();
    if (!out) fail_output(target, errno);
    out.close();
    if (!out) fail_output(target, errno);
    staged_.push_back(std::move(staged));
}

void OutputBatch::commit() {
    const DeferredInterrupts renaming;  // an interrupt comes after all of them or before any
    for (const std::unique_ptr<StagedFile>& staged : staged_) staged->commit();
}

void write_file(const std::filesystem::path& path, std::string_view bytes) {
    OutputBatch batch;
    batch.write(path, bytes);
    batch.commit();
}

void write_stream(const std::filesystem::path& path, const std::function<void(std::ostream&)>& fill) {
    OutputBatch batch;
    batch.write_stream(path, fill);
    batch.commit();
}

}  // namespace cutaway::io

#pragma once
// A buffered std::streambuf in front of another that reports every `report_every` bytes
// written ("generate: wrote 512 MB"), so a multi-gigabyte write shows it is alive.
#include <cstddef>
#include <ostream>
#include <streambuf>
#include <vector>

namespace cutaway::generators {

class WriteProgressBuf : public std::streambuf {
public:
    /// `target`: where the bytes go; `log`: progress lines (null: none).
    WriteProgressBuf(std::streambuf* target, std::ostream* log, std::size_t report_every = std::size_t(256) << 20);
    ~WriteProgressBuf() override;
    WriteProgressBuf(const WriteProgressBuf&) = delete;
    WriteProgressBuf& operator=(const WriteProgressBuf&) = delete;

    std::size_t bytes_written() const { return written_ + std::size_t(pptr() - pbase()); }

protected:
    int_type overflow(int_type ch) override;
    int sync() override;

private:
    bool flush_buffer();

    std::streambuf* target_;
    std::ostream* log_;
    std::size_t report_every_;
    std::size_t next_report_;
    std::size_t written_ = 0;
    std::vector<char> buffer_;
};

}  // namespace cutaway::generators

#include "write_progress.h"

namespace cutaway::generators {

WriteProgressBuf::WriteProgressBuf(std::streambuf* target, std::ostream* log, std::size_t report_every)
    : target_(target), log_(log), report_every_(report_every), next_report_(report_every), buffer_(std::size_t(1) << 20) {
    setp(buffer_.data(), buffer_.data() + buffer_.size());
}

WriteProgressBuf::~WriteProgressBuf() { flush_buffer(); }

bool WriteProgressBuf::flush_buffer() {
    const std::streamsize pending = pptr() - pbase();
    if (pending > 0 && target_->sputn(pbase(), pending) != pending) return false;
    written_ += std::size_t(pending);
    setp(buffer_.data(), buffer_.data() + buffer_.size());
    if (log_ && written_ >= next_report_) {
        *log_ << "generate: wrote " << (written_ >> 20) << " MiB" << std::endl;
        while (next_report_ <= written_) next_report_ += report_every_;
    }
    return true;
}

WriteProgressBuf::int_type WriteProgressBuf::overflow(int_type ch) {
    if (!flush_buffer()) return traits_type::eof();
    if (!traits_type::eq_int_type(ch, traits_type::eof())) {
        *pptr() = traits_type::to_char_type(ch);
        pbump(1);
    }
    return traits_type::not_eof(ch);
}

int WriteProgressBuf::sync() { return flush_buffer() && target_->pubsync() == 0 ? 0 : -1; }

}  // namespace cutaway::generators

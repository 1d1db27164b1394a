#pragma once
// The one error type of GRDECL input: where (file, line, keyword), what was expected, what was found.
#include <string>

#include "io/bad_input_error.h"

namespace cutaway::grid {

struct GrdeclErrorInfo {
    std::string file;     // path as given, or a name for in-memory text
    int line = 0;         // 1-based; 0 when not tied to a line
    std::string keyword;  // the keyword being read, empty outside any keyword
    std::string expected;
    std::string found;
};

class GrdeclError : public io::BadInputError {
public:
    explicit GrdeclError(GrdeclErrorInfo info);
    const GrdeclErrorInfo& info() const { return info_; }

private:
    GrdeclErrorInfo info_;
};

}  // namespace cutaway::grid

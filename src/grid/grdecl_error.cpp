#include "grid/grdecl_error.h"

namespace cutaway::grid {

static std::string describe(const GrdeclErrorInfo& info) {
    // Appended piece by piece: GCC 12 reports a false -Wrestrict on chained operator+.
    std::string text = info.file;
    if (info.line > 0) text.append(":").append(std::to_string(info.line));
    text.append(": ");
    if (!info.keyword.empty()) text.append("keyword ").append(info.keyword).append(": ");
    text.append("expected ").append(info.expected).append(", found ").append(info.found);
    return text;
}

GrdeclError::GrdeclError(GrdeclErrorInfo info) : io::BadInputError(describe(info)), info_(std::move(info)) {}

}  // namespace cutaway::grid

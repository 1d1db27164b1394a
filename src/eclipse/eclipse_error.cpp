#include "eclipse/eclipse_error.h"

namespace cutaway::eclipse {

static std::string describe(const EclipseErrorInfo& info) {
    // Appended piece by piece, as GrdeclError does (GCC 12's false -Wrestrict on chained operator+).
    std::string text = info.file;
    text.append(": ");
    if (!info.array.empty()) text.append("array ").append(info.array).append(": ");
    text.append("expected ").append(info.expected).append(", found ").append(info.found);
    return text;
}

EclipseError::EclipseError(EclipseErrorInfo info) : io::BadInputError(describe(info)), info_(std::move(info)) {}

}  // namespace cutaway::eclipse

#pragma once
// The one error type of simulator output (EGRID, INIT, UNRST): which file, which array, what was
// expected and what was found. `cutaway` maps it to exit code 2 like GrdeclError.
#include <string>

#include "io/bad_input_error.h"

namespace cutaway::eclipse {

struct EclipseErrorInfo {
    std::string file;   ///< path as given
    std::string array;  ///< the array being read (e.g. "ZCORN", "SWAT"), empty for the file as a whole
    std::string expected;
    std::string found;
};

class EclipseError : public io::BadInputError {
public:
    explicit EclipseError(EclipseErrorInfo info);
    const EclipseErrorInfo& info() const { return info_; }

private:
    EclipseErrorInfo info_;
};

}  // namespace cutaway::eclipse

#pragma once
// The base of every refusal of what the user gave: a malformed file (GRDECL, SEG-Y, simulator
// results), an unusable output path. The message names the file, keyword or field and what was
// expected; `cutaway` maps every such error to exit code 2 (app_core/exit_status.h).
#include <stdexcept>
#include <string>

namespace cutaway::io {

class BadInputError : public std::runtime_error {
public:
    explicit BadInputError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace cutaway::io

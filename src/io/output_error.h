#pragma once
// An output that could not be written (missing directory, disk full, no permission): the message
// names the path and the operating system's reason. `cutaway` exits with code 2 for it.
#include <string>

#include "io/bad_input_error.h"

namespace cutaway::io {

class OutputError : public BadInputError {
public:
    explicit OutputError(const std::string& message) : BadInputError(message) {}
};

}  // namespace cutaway::io

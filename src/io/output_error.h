#pragma once
// An output that could not be written (missing directory, disk full, no permission): the message
// names the path and the operating system's reason. `cutaway` exits with code 2 for it.
#include <stdexcept>
#include <string>

namespace cutaway::io {

class OutputError : public std::runtime_error {
public:
    explicit OutputError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace cutaway::io

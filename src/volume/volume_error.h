#pragma once
// Bad seismic input (a file that is not usable SEG-Y, or a cube too large): the message names the
// file, the field and what was expected. `cutaway` exits with code 2 for it.
#include <stdexcept>
#include <string>

namespace cutaway::volume {

class VolumeError : public std::runtime_error {
public:
    explicit VolumeError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace cutaway::volume

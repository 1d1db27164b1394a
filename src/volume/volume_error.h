#pragma once
// Bad seismic input (a file that is not usable SEG-Y, or a cube too large): the message names the
// file, the field and what was expected. `cutaway` exits with code 2 for it.
#include <string>

#include "io/bad_input_error.h"

namespace cutaway::volume {

class VolumeError : public io::BadInputError {
public:
    explicit VolumeError(const std::string& message) : io::BadInputError(message) {}
};

}  // namespace cutaway::volume

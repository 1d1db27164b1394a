#pragma once
// The one mapping from a failure to `cutaway`'s exit code and message, shared by every command and
// by the ranks of a distributed render (README lists the codes).
#include <exception>
#include <string>

#include "app_core/exit_codes.h"

namespace cutaway::app {

struct ExitStatus {
    int code = exit_failure;
    std::string message;  ///< one line, without "cutaway: " and the newline
};

/// What `main` reports and returns for `error`.
ExitStatus exit_status_of(const std::exception_ptr& error);

}  // namespace cutaway::app

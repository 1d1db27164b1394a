#pragma once
// The one mapping from a failure to `cutaway`'s exit code and message, shared by every command and
// by the ranks of a distributed render (README lists the codes).
#include <exception>
#include <string>

namespace cutaway::app {

inline constexpr int exit_failure = 1;        ///< an unexpected error (a bug: please report it)
inline constexpr int exit_bad_input = 2;      ///< a file, option or output refused; nothing written
inline constexpr int exit_out_of_memory = 3;  ///< an allocation failed
inline constexpr int exit_gl_failure = 4;     ///< no usable OpenGL context, or a GL error

struct ExitStatus {
    int code = exit_failure;
    std::string message;  ///< one line, without "cutaway: " and the newline
};

/// What `main` reports and returns for `error`.
ExitStatus exit_status_of(const std::exception_ptr& error);

}  // namespace cutaway::app

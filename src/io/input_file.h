#pragma once
// What an input path names when it is not a readable regular file, in words for a refusal: a
// missing file, a loop of symbolic links, a directory, a FIFO (whose open would block until a
// writer comes), a device.
#include <filesystem>
#include <string>

namespace cutaway::io {

/// Empty when `path` is a regular file; otherwise what was found instead ("no such file", "a loop
/// of symbolic links (ELOOP)", "a FIFO", ...), for "expected a readable file, found ...".
std::string input_file_problem(const std::filesystem::path& path);

}  // namespace cutaway::io

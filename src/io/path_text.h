#pragma once
// Paths as messages show them: a path of thousands of characters would make a refusal as long, so
// only its end (which names the file) is kept.
#include <filesystem>
#include <string>

namespace cutaway::io {

/// The longest path shown whole in a message (characters); longer ones keep their last part.
constexpr std::size_t shown_path_length = 120;

/// `path` as text, shortened to "...END" of shown_path_length characters when longer.
std::string shown_path(const std::filesystem::path& path);

}  // namespace cutaway::io

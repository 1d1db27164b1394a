#include "io/path_text.h"

namespace cutaway::io {

std::string shown_path(const std::filesystem::path& path) {
    const std::string& text = path.native();
    if (text.size() <= shown_path_length) return text;
    return "..." + text.substr(text.size() - (shown_path_length - 3));
}

}  // namespace cutaway::io

#include "eclipse/eclio_access.h"

namespace cutaway::eclipse {

std::string first_line(const std::string& message) {
    std::string line = message.substr(0, message.find('\n'));
    if (const std::size_t end = line.find("] "); !line.empty() && line.front() == '[' && end != std::string::npos)
        line.erase(0, end + 2);
    return line.empty() ? "an unreadable file" : line;
}

std::string unit_system_name(int code) {
    switch (code) {
        case 1: return "METRIC";
        case 2: return "FIELD";
        case 3: return "LAB";
        case 4: return "PVT-M";
        default: return {};
    }
}

void require_within_memory(const std::filesystem::path& file, const std::string& what, std::size_t needed_bytes,
                           std::size_t limit_bytes) {
    if (needed_bytes > limit_bytes)
        throw EclipseError({file.string(), "",
                            "at most " + std::to_string(limit_bytes) + " bytes (--memory-limit-gb) to read " + what,
                            std::to_string(needed_bytes) + " bytes needed"});
}

}  // namespace cutaway::eclipse

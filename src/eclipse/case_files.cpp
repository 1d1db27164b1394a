#include "eclipse/case_files.h"

#include <algorithm>
#include <cctype>
#include <system_error>

namespace cutaway::eclipse {
namespace {

namespace fs = std::filesystem;

std::string upper(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::toupper(c)); });
    return text;
}

bool is_file(const fs::path& path) {
    std::error_code ignored;
    return fs::is_regular_file(path, ignored);
}

/// `egrid` with its extension replaced by `extension` (upper case) in the EGRID's letter case.
std::optional<fs::path> sibling(const fs::path& egrid, const std::string& extension) {
    const bool lower_case = egrid.extension().string() == ".egrid";
    std::string wanted = extension;
    if (lower_case) std::transform(wanted.begin(), wanted.end(), wanted.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    fs::path path = egrid;
    path.replace_extension(wanted);
    return is_file(path) ? std::optional<fs::path>(path) : std::nullopt;
}

CaseFiles case_of(const fs::path& egrid) {
    return {egrid, sibling(egrid, ".INIT"), sibling(egrid, ".UNRST")};
}

}  // namespace

std::optional<CaseFiles> find_case_files(const std::string& model) {
    const fs::path path(model);
    if (upper(path.extension().string()) == ".EGRID") return case_of(path);
    if (model.empty() || is_file(path)) return std::nullopt;
    for (const char* extension : {".EGRID", ".egrid"})
        if (const fs::path egrid(model + extension); is_file(egrid)) return case_of(egrid);
    return std::nullopt;
}

}  // namespace cutaway::eclipse

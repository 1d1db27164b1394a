#include "wells/well_selection.h"

#include <algorithm>
#include <cctype>
#include <stdexcept>

namespace cutaway::wells {
namespace {

std::string upper(std::string text) {
    for (char& c : text) c = char(std::toupper(static_cast<unsigned char>(c)));
    return text;
}

std::vector<std::string> split_names(const std::string& value) {
    std::vector<std::string> names;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = value.find(',', start);
        const std::string name = value.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        if (name.empty())
            throw std::invalid_argument("--wells '" + value + "': expected all, none, a FILE or NAME[,NAME...], found an empty name");
        names.push_back(name);
        if (comma == std::string::npos) return names;
        start = comma + 1;
    }
}

}  // namespace

bool WellsOption::draws() const { return which == Which::all || which == Which::named || (which == Which::unset && file); }

bool names_a_file(const std::string& value) {
    std::error_code error;
    if (std::filesystem::is_regular_file(value, error) || value.find('/') != std::string::npos) return true;
    const std::string extension = upper(std::filesystem::path(value).extension().string());
    return extension == ".DATA" || extension == ".GRDECL" || extension == ".INC" || extension == ".SCH";
}

WellsOption parse_wells_option(const std::vector<std::string>& values) {
    WellsOption option;
    for (const std::string& value : values) {
        if (names_a_file(value)) {
            if (option.file) throw std::invalid_argument("--wells: expected at most one FILE, found '" + option.file->string() + "' and '" + value + "'");
            option.file = value;
            continue;
        }
        if (option.which != WellsOption::Which::unset)
            throw std::invalid_argument("--wells '" + value + "': expected one selection (all, none or NAME[,NAME...]) besides a FILE, found a second");
        if (value == "all") option.which = WellsOption::Which::all;
        else if (value == "none") option.which = WellsOption::Which::none;
        else {
            option.which = WellsOption::Which::named;
            option.names = split_names(value);
        }
    }
    return option;
}

std::vector<Well> select_wells(const std::vector<Well>& wells, const WellsOption& option, const std::string& source) {
    if (!option.draws()) return {};
    if (option.which != WellsOption::Which::named) return wells;
    for (const std::string& name : option.names)
        if (std::none_of(wells.begin(), wells.end(), [&](const Well& w) { return w.name == name; })) {
            std::string known;
            for (const Well& w : wells) known += (known.empty() ? "" : ", ") + w.name;
            throw std::invalid_argument("--wells: no well named '" + name + "' in " + source + " (its wells: " +
                                        (known.empty() ? std::string("none") : known) + ")");
        }
    std::vector<Well> selected;
    for (const Well& w : wells)
        if (std::find(option.names.begin(), option.names.end(), w.name) != option.names.end()) selected.push_back(w);
    return selected;
}

}  // namespace cutaway::wells

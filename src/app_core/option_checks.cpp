#include "app_core/option_checks.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "io/staged_file.h"

namespace cutaway::app {

std::string number_text(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", value);
    return buffer;
}

namespace {

/// At most 40 characters of what the user typed, so a huge argument is not echoed whole.
std::string shown(const std::string& text) {
    constexpr std::size_t limit = 40;
    return "'" + (text.size() > limit ? text.substr(0, limit) + "..." : text) + "'";
}

CLI::Validator finite_range(double low, double high, bool low_open, const std::string& unit, const std::string& name) {
    const std::string range = (low_open ? "(" : "[") + number_text(low) + ", " + number_text(high) + "]" +
                              (unit.empty() ? "" : " " + unit);
    const bool bounded = std::isfinite(low) || std::isfinite(high);
    const std::string description = (name.empty() ? "" : name + " to be ") + "a finite number" + (bounded ? " in " + range : "");
    return CLI::Validator(
        [=](std::string& text) -> std::string {
            double value = 0;
            const char* first = text.data();
            const char* last = first + text.size();
            if (first != last && *first == '+') ++first;
            const auto [end, error] = std::from_chars(first, last, value);
            if (error != std::errc() || end != last || text.empty())
                return "expected " + description + ", found " + shown(text);
            const bool inside = std::isfinite(value) && (low_open ? value > low : value >= low) && value <= high;
            if (!inside) return "expected " + description + ", found " + shown(text);
            return {};
        },
        range);
}

}  // namespace

CLI::Validator finite_in(double low, double high, const std::string& unit, const std::string& name) {
    return finite_range(low, high, false, unit, name);
}

CLI::Validator finite_above(double low, double high, const std::string& unit, const std::string& name) {
    return finite_range(low, high, true, unit, name);
}

CLI::Validator finite_number() {
    return finite_range(-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(), false, "", "");
}

void check_orbit_values(CLI::Option& option, double max_distance) {
    option.check(finite_in(-360, 360, "degrees", "AZ").application_index(0));
    option.check(finite_in(-89, 89, "degrees", "EL").application_index(1));
    option.check(finite_in(0, max_distance, "", "DIST").application_index(2));
}

CLI::Validator one_of(const std::vector<std::string>& names) {
    std::string known;
    for (const std::string& name : names) known += (known.empty() ? "" : "|") + name;
    return CLI::Validator(
        [names, known](std::string& text) -> std::string {
            if (std::find(names.begin(), names.end(), text) != names.end()) return {};
            return "expected one of " + known + ", found " + shown(text);
        },
        known);
}

namespace {

/// Whether `text` is well-formed UTF-8 (no overlong forms, surrogates or code points past U+10FFFF).
bool is_utf8(const std::string& text) {
    std::size_t n = 0;
    while (n < text.size()) {
        const auto lead = static_cast<unsigned char>(text[n]);
        const std::size_t length = lead < 0x80 ? 1 : (lead >> 5) == 0x6 ? 2 : (lead >> 4) == 0xE ? 3 : (lead >> 3) == 0x1E ? 4 : 0;
        if (length == 0 || n + length > text.size()) return false;
        std::uint32_t code = length == 1 ? lead : lead & (0x7F >> length);
        for (std::size_t k = 1; k < length; ++k) {
            const auto next = static_cast<unsigned char>(text[n + k]);
            if ((next >> 6) != 0x2) return false;
            code = (code << 6) | (next & 0x3F);
        }
        const std::uint32_t smallest[5] = {0, 0, 0x80, 0x800, 0x10000};
        if (code < smallest[length] || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return false;
        n += length;
    }
    return true;
}

}  // namespace

CLI::Validator utf8_text() {
    return CLI::Validator(
        [](std::string& text) -> std::string {
            if (is_utf8(text)) return {};
            std::string printable = text;
            for (char& c : printable)
                if (static_cast<unsigned char>(c) > 126 || static_cast<unsigned char>(c) < 32) c = '?';
            // The end of a path names the file: show the last 60 characters.
            constexpr std::size_t tail = 60;
            if (printable.size() > tail) printable = "..." + printable.substr(printable.size() - tail);
            return "expected UTF-8 text, found '" + printable + "'";
        },
        "UTF-8");
}

CLI::Validator property_name() {
    const CLI::Validator utf8 = utf8_text();
    return CLI::Validator(
        [utf8](std::string& text) -> std::string {
            if (text.empty()) return "expected a property keyword (PORO, SWAT, ...), found an empty one";
            return utf8(text);
        },
        "NAME");
}

CLI::Validator writable_output() {
    return CLI::Validator([](std::string& path) { return io::output_path_problem(path); }, "FILE");
}

CLI::Validator writable_output_directory() {
    return CLI::Validator([](std::string& path) { return io::output_directory_problem(path); }, "DIR");
}

void refuse_overwrites(const std::vector<io::NamedFile>& inputs, const std::vector<io::NamedFile>& outputs) {
    if (const std::string problem = io::overwrite_problem(inputs, outputs); !problem.empty())
        throw std::invalid_argument(problem);
}

std::size_t gib_to_bytes(double gib) { return std::size_t(gib * double(std::size_t(1) << 30)); }

void add_memory_limit_option(CLI::App& command, double& gib, const std::string& what) {
    command.add_option("--memory-limit-gb", gib, "refuse " + what + " needing more memory than this (GiB)")
        ->capture_default_str()
        ->check(finite_above(0, max_memory_limit_gib, "GiB"));
}

std::string memory_limit_problem(std::size_t bytes_needed, std::size_t limit_bytes, const std::string& what) {
    const double gib = double(std::size_t(1) << 30);
    return "expected " + what + " within the memory limit of " + number_text(double(limit_bytes) / gib) +
           " GiB (--memory-limit-gb), found " + number_text(double(bytes_needed) / gib) + " GiB needed";
}

}  // namespace cutaway::app

#include "volumes/cut_volume_spec.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <vector>

namespace cutaway::volumes {
namespace {

std::vector<std::string> split_commas(std::string_view text) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    for (;;) {
        const std::size_t comma = text.find(',', start);
        parts.emplace_back(text.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
        if (comma == std::string_view::npos) return parts;
        start = comma + 1;
    }
}

/// The whole of `text` as a finite number (strtod: the same correctly rounded double a JSON file's
/// number gives, so a spec and its JSON entry cut alike).
double parse_number(const std::string& text, const std::string& kind, std::size_t index) {
    char* end = nullptr;
    errno = 0;
    const double value = text.empty() ? 0 : std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(value))
        throw std::invalid_argument(kind + " number " + std::to_string(index + 1) + ": expected a finite number, found '" +
                                    text + "'");
    return value;
}

std::vector<double> parse_numbers(std::string_view body, const std::string& kind, std::size_t expected,
                                  const char* form) {
    const std::vector<std::string> parts = split_commas(body);
    if (parts.size() != expected)
        throw std::invalid_argument(kind + ": expected " + std::to_string(expected) + " numbers " + form + ", found " +
                                    std::to_string(parts.size()));
    std::vector<double> values;
    for (std::size_t i = 0; i < parts.size(); ++i) values.push_back(parse_number(parts[i], kind, i));
    return values;
}

CutVolume parse_box(std::string_view body) {
    const std::vector<double> v = parse_numbers(body, "box", 6, "X0,Y0,Z0,X1,Y1,Z1");
    return BoxVolume{{std::min(v[0], v[3]), std::min(v[1], v[4]), std::min(v[2], v[5])},
                     {std::max(v[0], v[3]), std::max(v[1], v[4]), std::max(v[2], v[5])}};
}

CutVolume parse_cylinder(std::string_view body) {
    const std::vector<double> v = parse_numbers(body, "cylinder", 7, "X0,Y0,Z0,X1,Y1,Z1,R");
    return CylinderVolume{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}, v[6]};
}

CutVolume parse_well(std::string_view body) {
    const std::vector<std::string> parts = split_commas(body);
    if (parts.size() > 2) throw std::invalid_argument("well: expected NAME or NAME,R, found " + std::to_string(parts.size()) + " fields");
    WellVolume well{parts[0], std::nullopt};
    if (parts.size() == 2) well.radius = parse_number(parts[1], "well", 1);
    return well;
}

CutVolume parse_body(std::string_view kind, std::string_view body) {
    if (kind == "box") return parse_box(body);
    if (kind == "cylinder") return parse_cylinder(body);
    if (kind == "well") return parse_well(body);
    if (kind == "mesh") return MeshVolume{std::string(body)};
    throw std::invalid_argument("expected one of " + cut_volume_spec_forms());
}

}  // namespace

std::string cut_volume_spec_forms() {
    return "box:X0,Y0,Z0,X1,Y1,Z1 | cylinder:X0,Y0,Z0,X1,Y1,Z1,R | well:NAME[,R] | mesh:FILE";
}

CutVolume parse_cut_volume_spec(std::string_view spec) {
    try {
        const std::size_t colon = spec.find(':');
        if (colon == std::string_view::npos) throw std::invalid_argument("expected KIND:VALUES, one of " + cut_volume_spec_forms());
        CutVolume volume = parse_body(spec.substr(0, colon), spec.substr(colon + 1));
        check_volume(volume);
        return volume;
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("--cut-volume '" + std::string(spec) + "': " + e.what());
    }
}

}  // namespace cutaway::volumes

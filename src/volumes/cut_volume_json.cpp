#include "volumes/cut_volume_json.h"

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "io/input_file.h"

namespace cutaway::volumes {
namespace {

using nlohmann::json;

/// Bytes of memory a JSON document takes per byte of text while parsed (nlohmann's nodes are
/// larger than the text they come from; a list of volumes is small in any case).
constexpr std::size_t json_bytes_per_text_byte = 16;

std::string found(const json& value) {
    std::string text = value.dump();
    if (text.size() > 40) text = text.substr(0, 37) + "...";
    return text;
}

class Entry {
public:
    Entry(const json& entry, std::string where) : entry_(entry), where_(std::move(where)) {}

    [[noreturn]] void fail(const std::string& field, const std::string& problem) const {
        throw std::invalid_argument(where_ + "." + field + ": " + problem);
    }
    const json& field(const std::string& name) const {
        if (!entry_.contains(name)) fail(name, "missing");
        return entry_.at(name);
    }
    bool field_present(const std::string& name) const { return entry_.contains(name); }
    double number(const std::string& name) const {
        const json& value = field(name);
        if (!value.is_number()) fail(name, "expected a number, found " + found(value));
        return value.get<double>();
    }
    grid::Point3 point(const std::string& name) const {
        const json& value = field(name);
        if (!value.is_array() || value.size() != 3 || !value[0].is_number() || !value[1].is_number() || !value[2].is_number())
            fail(name, "expected [X, Y, Z] (three numbers), found " + found(value));
        return {value[0].get<double>(), value[1].get<double>(), value[2].get<double>()};
    }
    std::string text(const std::string& name) const {
        const json& value = field(name);
        if (!value.is_string()) fail(name, "expected a string, found " + found(value));
        return value.get<std::string>();
    }
    /// Refuses fields other than "kind" and `allowed`.
    void only(std::set<std::string> allowed) const {
        allowed.insert("kind");
        for (const auto& [key, value] : entry_.items())
            if (!allowed.count(key)) fail(key, "not a field of this kind (expected " + list(allowed) + ")");
    }

private:
    static std::string list(const std::set<std::string>& names) {
        std::string text;
        for (const std::string& n : names) text += (text.empty() ? "" : ", ") + n;
        return text;
    }
    const json& entry_;
    std::string where_;
};

CutVolume parse_entry(const Entry& e, const std::string& kind, const std::filesystem::path& base_dir) {
    if (kind == "box") {
        e.only({"min", "max"});
        const grid::Point3 a = e.point("min"), b = e.point("max");
        return BoxVolume{{std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)},
                         {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)}};
    }
    if (kind == "cylinder") {
        e.only({"from", "to", "radius"});
        return CylinderVolume{e.point("from"), e.point("to"), e.number("radius")};
    }
    if (kind == "well") {
        e.only({"name", "radius"});
        WellVolume well{e.text("name"), std::nullopt};
        if (e.field_present("radius")) well.radius = e.number("radius");
        return well;
    }
    if (kind == "mesh") {
        e.only({"file"});
        const std::filesystem::path file = e.text("file");
        return MeshVolume{(file.is_relative() && !file.empty() ? base_dir / file : file).string()};
    }
    e.fail("kind", "expected box, cylinder, well or mesh, found '" + kind + "'");
}

}  // namespace

std::vector<CutVolume> parse_cut_volumes_json(const std::string& text, const std::filesystem::path& base_dir,
                                              const std::string& source) {
    json document;
    try {
        document = json::parse(text);
    } catch (const json::parse_error& e) {
        throw std::invalid_argument(source + ": expected a JSON document {\"volumes\": [...]}, found a syntax error at byte " +
                                    std::to_string(e.byte));
    }
    if (!document.is_object() || !document.contains("volumes") || !document["volumes"].is_array())
        throw std::invalid_argument(source + ": expected {\"volumes\": [...]} at the top level");
    for (const auto& [key, value] : document.items())
        if (key != "volumes") throw std::invalid_argument(source + ": " + key + ": not a field (expected only \"volumes\")");
    std::vector<CutVolume> volumes;
    const json& list = document["volumes"];
    for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string where = source + ": volumes[" + std::to_string(i) + "]";
        if (!list[i].is_object()) throw std::invalid_argument(where + ": expected an object {\"kind\": ...}, found " + found(list[i]));
        const Entry entry(list[i], where);
        CutVolume volume = parse_entry(entry, entry.text("kind"), base_dir);
        try {
            check_volume(volume);
        } catch (const std::invalid_argument& e) {
            throw std::invalid_argument(where + ": " + e.what());
        }
        volumes.push_back(std::move(volume));
    }
    return volumes;
}

std::vector<CutVolume> read_cut_volumes_file(const std::string& path, std::size_t memory_limit_bytes) {
    if (const std::string problem = io::input_file_problem(path); !problem.empty())
        throw std::invalid_argument("--cut-volumes " + path + ": expected a readable JSON file, found " + problem);
    const std::uintmax_t bytes = std::filesystem::file_size(path);
    if (bytes > memory_limit_bytes / json_bytes_per_text_byte)
        throw std::invalid_argument("--cut-volumes " + path + ": " + std::to_string(bytes) +
                                    " bytes would need more than --memory-limit-gb allows");
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in) throw std::invalid_argument("--cut-volumes " + path + ": could not be read");
    return parse_cut_volumes_json(text.str(), std::filesystem::path(path).parent_path(), path);
}

nlohmann::json volume_json(const CutVolume& volume) {
    struct ToJson {
        json operator()(const BoxVolume& b) const {
            return {{"kind", "box"}, {"min", {b.min.x, b.min.y, b.min.z}}, {"max", {b.max.x, b.max.y, b.max.z}}};
        }
        json operator()(const CylinderVolume& c) const {
            return {{"kind", "cylinder"}, {"from", {c.from.x, c.from.y, c.from.z}}, {"to", {c.to.x, c.to.y, c.to.z}}, {"radius", c.radius}};
        }
        json operator()(const WellVolume& w) const {
            json entry{{"kind", "well"}, {"name", w.name}};
            if (w.radius) entry["radius"] = *w.radius;
            return entry;
        }
        json operator()(const MeshVolume& m) const { return {{"kind", "mesh"}, {"file", m.file}}; }
    };
    return std::visit(ToJson{}, volume);
}

nlohmann::json cut_volumes_document(const std::vector<CutVolume>& volumes) {
    json list = json::array();
    for (const CutVolume& volume : volumes) {
        json entry = volume_json(volume);
        if (const auto* mesh = std::get_if<MeshVolume>(&volume)) entry["file"] = std::filesystem::absolute(mesh->file).string();
        list.push_back(entry);
    }
    return {{"volumes", list}};
}

}  // namespace cutaway::volumes

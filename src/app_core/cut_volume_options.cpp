#include "app_core/cut_volume_options.h"

#include <stdexcept>

#include "app_core/option_checks.h"
#include "cutaway/setting_names.h"
#include "volumes/cut_volume_json.h"
#include "volumes/cut_volume_spec.h"

namespace cutaway::app {

nlohmann::json CutVolumeOptions::describe() const {
    return {{"primaries", primaries}, {"cut_volume", specs}, {"cut_volumes_file", file}};
}

void add_cut_volume_options(CLI::App& c, CutVolumeOptions& o) {
    c.add_option("--cut-volume", o.specs,
                 "a cut volume in model coordinates (repeatable): " + volumes::cut_volume_spec_forms() +
                     " (a PLY or OBJ closed mesh)")
        ->check(CLI::Validator(
            [](std::string& spec) -> std::string {
                try {
                    volumes::parse_cut_volume_spec(spec);
                    return {};
                } catch (const std::invalid_argument& e) {
                    const std::string message = e.what();
                    return message.substr(message.find('\'') == std::string::npos ? 0 : message.find('\''));
                }
            },
            "SPEC"));
    c.add_option("--cut-volumes", o.file,
                 "a JSON list of cut volumes {\"volumes\": [{\"kind\": \"box\", \"min\": [...], \"max\": [...]}, ...]} "
                 "(the file the viewer saves)")
        ->check(utf8_text());
    const std::vector<std::string> names = pipeline::choice_names(pipeline::primaries_choices());
    c.add_option("--primaries", o.primaries,
                 pipeline::joined_choices(names) + ": property (chosen by --property's --range or --primary-fraction, or "
                                                   "--select-by) | none (no primaries: the cut volumes alone cut)")
        ->check(one_of(names));
}

void finish_cut_volume_options(CutVolumeOptions& o) {
    o.parsed.clear();
    for (const std::string& spec : o.specs) o.parsed.push_back(volumes::parse_cut_volume_spec(spec));
}

void check_primaries_none(const CutVolumeOptions& o, const std::string& selects_primaries, bool only_primaries) {
    if (o.primaries != "none") return;
    if (!o.any()) throw std::invalid_argument("--primaries none: expected --cut-volume or --cut-volumes (nothing would cut)");
    if (!selects_primaries.empty())
        throw std::invalid_argument("--primaries none: " + selects_primaries + " selects primaries; give one or the other");
    if (only_primaries) throw std::invalid_argument("--primaries none: --only primaries would draw nothing");
}

nlohmann::json CutVolumeSet::describe() const {
    nlohmann::json list = nlohmann::json::array();
    for (std::size_t i = 0; i < volumes.size(); ++i) {
        nlohmann::json entry = volumes::volume_json(volumes[i]);
        entry["spec"] = volumes::spec_text(volumes[i]);
        entry["triangles"] = i < meshes.size() ? meshes[i].triangles.size() : 0;
        list.push_back(entry);
    }
    return list;
}

CutVolumeSet load_cut_volumes(const CutVolumeOptions& o, const pipeline::ModelFrame& frame,
                              const volumes::WellPaths& wells, std::size_t memory_limit_bytes) {
    std::vector<volumes::CutVolume> list;
    if (!o.file.empty()) list = volumes::read_cut_volumes_file(o.file, memory_limit_bytes);
    list.insert(list.end(), o.parsed.begin(), o.parsed.end());
    return build_cut_volumes(std::move(list), frame, wells, memory_limit_bytes);
}

CutVolumeSet build_cut_volumes(std::vector<volumes::CutVolume> list, const pipeline::ModelFrame& frame,
                               const volumes::WellPaths& wells, std::size_t memory_limit_bytes) {
    CutVolumeSet set;
    set.volumes = std::move(list);
    // Render x and y are the model's, shifted: their extents are the model's.
    grid::Box3 bounds;
    bounds.extend(grid::Point3{frame.render_min.x, frame.render_min.y, 0});
    bounds.extend(grid::Point3{frame.render_max.x, frame.render_max.y, 0});
    const volumes::VolumeBuildContext context{&wells, volumes::default_well_radius(bounds), memory_limit_bytes};
    for (const volumes::CutVolume& volume : set.volumes) set.meshes.push_back(volumes::build_volume_mesh(volume, context));
    return set;
}

}  // namespace cutaway::app

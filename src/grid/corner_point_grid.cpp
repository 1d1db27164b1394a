#include "grid/corner_point_grid.h"

#include <algorithm>
#include <stdexcept>

namespace cutaway::grid {

CornerPointGrid::CornerPointGrid(GridDims dims, std::vector<double> coord, ZcornStore zcorn,
                                 std::vector<std::uint8_t> actnum)
    : dims_(dims), coord_(std::move(coord)), zcorn_(std::move(zcorn)), actnum_(std::move(actnum)) {
    if (dims.nx <= 0 || dims.ny <= 0 || dims.nz <= 0)
        throw std::invalid_argument("CornerPointGrid: dimensions must be positive");
    if (coord_.size() != dims.coord_value_count())
        throw std::invalid_argument("CornerPointGrid: COORD has " + std::to_string(coord_.size()) +
                                    " values, expected " + std::to_string(dims.coord_value_count()));
    if (!(zcorn_.dims() == dims) || !zcorn_.complete())
        throw std::invalid_argument("CornerPointGrid: ZCORN store is incomplete or has other dimensions");
    if (actnum_.empty()) actnum_.assign(dims.cell_count(), 1);
    require_cell_sized("ACTNUM", actnum_.size());
    depth_direction_ = zcorn_.corner_depth(0, 0, 0, 0) <= zcorn_.corner_depth(0, 0, dims.nz - 1, 4) ? 1 : -1;
    active_count_ = std::size_t(std::count_if(actnum_.begin(), actnum_.end(), [](std::uint8_t a) { return a != 0; }));
}

Pillar CornerPointGrid::pillar(int pi, int pj) const {
    const double* c = coord_.data() + 6 * dims_.pillar_index(pi, pj);
    return {{c[0], c[1], c[2]}, {c[3], c[4], c[5]}};
}

void CornerPointGrid::require_cell_sized(const std::string& name, std::size_t size) const {
    if (size != dims_.cell_count())
        throw std::invalid_argument(name + ": " + std::to_string(size) + " values, expected one per cell (" +
                                    std::to_string(dims_.cell_count()) + ")");
}

void CornerPointGrid::set_property(const std::string& name, std::vector<float> values) {
    require_cell_sized(name, values.size());
    int_properties_.erase(name);
    float_properties_[name] = std::move(values);
}

void CornerPointGrid::set_int_property(const std::string& name, std::vector<std::int32_t> values) {
    require_cell_sized(name, values.size());
    float_properties_.erase(name);
    int_properties_[name] = std::move(values);
}

template <typename Map>
static auto find_or_null(const Map& map, const std::string& name) -> const typename Map::mapped_type* {
    const auto it = map.find(name);
    return it == map.end() ? nullptr : &it->second;
}

template <typename Map>
static std::vector<std::string> keys_of(const Map& map) {
    std::vector<std::string> names;
    for (const auto& entry : map) names.push_back(entry.first);
    return names;
}

const std::vector<float>* CornerPointGrid::property(const std::string& name) const {
    return find_or_null(float_properties_, name);
}

const std::vector<std::int32_t>* CornerPointGrid::int_property(const std::string& name) const {
    return find_or_null(int_properties_, name);
}

std::vector<std::string> CornerPointGrid::property_names() const { return keys_of(float_properties_); }
std::vector<std::string> CornerPointGrid::int_property_names() const { return keys_of(int_properties_); }
std::vector<std::string> CornerPointGrid::dynamic_property_names() const { return keys_of(dynamic_properties_); }

void CornerPointGrid::clear_properties() {
    float_properties_.clear();
    int_properties_.clear();
    dynamic_properties_.clear();
}

void CornerPointGrid::add_dynamic_step(const std::string& name, std::vector<float> values) {
    require_cell_sized(name, values.size());
    dynamic_properties_[name].push_back(std::move(values));
}

void CornerPointGrid::declare_dynamic_steps(const std::string& name, std::size_t step_count) {
    auto& steps = dynamic_properties_[name];
    steps.clear();
    steps.resize(step_count);
}

void CornerPointGrid::set_dynamic_step(const std::string& name, std::size_t step, std::vector<float> values) {
    require_cell_sized(name, values.size());
    const auto found = dynamic_properties_.find(name);
    if (found == dynamic_properties_.end() || step >= found->second.size())
        throw std::invalid_argument(name + ": step " + std::to_string(step) + " of a property not declared with that many steps");
    for (auto& held : found->second) held = std::vector<float>();
    found->second[step] = std::move(values);
}

std::size_t CornerPointGrid::step_count(const std::string& name) const {
    const auto* steps = find_or_null(dynamic_properties_, name);
    return steps ? steps->size() : 0;
}

const std::vector<float>* CornerPointGrid::dynamic_property(const std::string& name, std::size_t step) const {
    const auto* steps = find_or_null(dynamic_properties_, name);
    return steps && step < steps->size() && !(*steps)[step].empty() ? &(*steps)[step] : nullptr;
}

std::size_t CornerPointGrid::geometry_bytes() const {
    return coord_.capacity() * sizeof(double) + zcorn_.bytes() + actnum_.capacity();
}

std::size_t CornerPointGrid::property_bytes() const {
    std::size_t bytes = 0;
    for (const auto& [name, values] : float_properties_) bytes += values.capacity() * sizeof(float);
    for (const auto& [name, values] : int_properties_) bytes += values.capacity() * sizeof(std::int32_t);
    for (const auto& [name, steps] : dynamic_properties_)
        for (const auto& values : steps) bytes += values.capacity() * sizeof(float);
    return bytes;
}

}  // namespace cutaway::grid

#include "presets.h"

#include <stdexcept>

namespace cutaway::generators {
namespace {

/// A preset: name, dims and lateral cell size (metres); the rest keeps the defaults, with more
/// faults on larger models.
GeneratorParameters preset(const char* name, grid::GridDims dims, double cell_size, double thickness, int faults) {
    GeneratorParameters p;
    p.name = name;
    p.dims = dims;
    p.length_x = cell_size * dims.nx;
    p.length_y = cell_size * dims.ny;
    p.thickness = thickness;
    p.fault_count = faults;
    p.poro_correlation_length = 8 * cell_size;
    return p;
}

}  // namespace

const std::vector<GeneratorParameters>& presets() {
    static const std::vector<GeneratorParameters> table = {
        preset("zaphirus", {30, 50, 5}, 100, 60, 3),
        preset("petra", {39, 42, 20}, 100, 120, 4),
        preset("opharine", {95, 80, 10}, 80, 100, 5),
        preset("sapphire", {124, 84, 20}, 80, 150, 6),
        preset("scale-1m", {200, 250, 20}, 50, 150, 8),
        preset("scale-10m", {500, 500, 40}, 25, 200, 10),
        preset("scale-100m", {1000, 1000, 100}, 15, 300, 12),
    };
    return table;
}

std::string preset_names() {
    std::string names;
    for (const GeneratorParameters& p : presets()) names += (names.empty() ? "" : ", ") + p.name;
    return names;
}

GeneratorParameters find_preset(const std::string& name) {
    for (const GeneratorParameters& p : presets())
        if (p.name == name) return p;
    throw std::invalid_argument("--preset: expected one of " + preset_names() + ", found '" + name + "'");
}

}  // namespace cutaway::generators

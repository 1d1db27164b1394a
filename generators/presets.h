#pragma once
// Named parameter sets: the paper's four models by cell count (Carvalho et al. 2016, Table 1)
// and two scale models for the speed and memory checks.
#include <string>
#include <vector>

#include "generator_parameters.h"

namespace cutaway::generators {

/// zaphirus (30x50x5 = 7,500), petra (39x42x20 = 32,760), opharine (95x80x10 = 76,000),
/// sapphire (124x84x20 = 208,320), scale-1m (200x250x20), scale-10m (500x500x40),
/// scale-100m (1000x1000x100).
const std::vector<GeneratorParameters>& presets();

/// The preset names, comma-separated ("zaphirus, petra, ...").
std::string preset_names();

/// The preset called `name`; throws std::invalid_argument ("--preset: expected one of NAMES, found
/// 'NAME'") for another name.
GeneratorParameters find_preset(const std::string& name);

}  // namespace cutaway::generators

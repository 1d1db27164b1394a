#include "generation_report.h"

#include <charconv>

namespace cutaway::generators {
namespace {

/// "`name` `index` `suffix` = `value`", built by appending (GCC 12 warns falsely on
/// "literal" + std::to_string(...)).
std::string indexed_line(const char* name, std::size_t index, const char* suffix, const std::string& value) {
    std::string line = name;
    line += ' ';
    line += std::to_string(index);
    line += suffix;
    line += " = ";
    line += value;
    return line;
}

std::string text(double value) {
    char buffer[32];
    return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, 4).ptr);
}

}  // namespace

std::vector<std::string> GenerationReport::lines() const {
    std::vector<std::string> out = {
        "cells = " + std::to_string(cells),
        "active_cells = " + std::to_string(active_cells),
        "pinched_cells (inactive) = " + std::to_string(pinched_cells),
        "clustered_inactive_cells = " + std::to_string(clustered_inactive),
        "inverted_cells (inactive) = " + std::to_string(inverted_cells),
        "degenerate_cells (inactive) = " + std::to_string(degenerate_cells),
        "repaired_interface_depths = " + std::to_string(repaired_depths),
        "pillar_depth_columns = " + std::to_string(depth_columns),
        "pillar_lean_scale = " + text(lean_scale),
        "key_horizons = " + std::to_string(horizons) + " (" + std::to_string(triangles_per_horizon) +
            " triangles each)",
    };
    for (std::size_t f = 0; f < faults.size(); ++f) out.push_back(indexed_line("fault", f, "", faults[f]));
    for (std::size_t n = 0; n < injectors.size(); ++n)
        out.push_back(indexed_line("injector", n, " column (i j, 0-based)", injectors[n]));
    std::string swept;
    for (double s : swept_fraction) {
        if (!swept.empty()) swept += ' ';
        swept += text(s);
    }
    if (!swept.empty()) out.push_back("swat_swept_fraction_per_step = " + swept);
    return out;
}

}  // namespace cutaway::generators

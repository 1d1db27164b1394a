#pragma once
// Shared by the generator tests: a quick model and writing it to text.
#include <sstream>
#include <string>

#include "generators/generator.h"
#include "generators/presets.h"
#include "grid/grdecl_writer.h"

namespace cutaway::generators::testing {

/// A faulted model of a few thousand cells that generates in milliseconds.
inline GeneratorParameters small_parameters() {
    GeneratorParameters p = find_preset("zaphirus");
    p.name = "test-small";
    p.dims = {24, 30, 6};
    p.length_x = 2400;
    p.length_y = 3000;
    return p;
}

inline GeneratedModel generate_quietly(const GeneratorParameters& p) {
    ProgressLog silent(nullptr);
    return generate_model(p, silent);
}

/// The GRDECL text the `generate` command writes.
inline std::string grdecl_text(const GeneratorParameters& p) {
    const GeneratedModel model = generate_quietly(p);
    grid::GrdeclWriteOptions options;
    options.header_comments = header_lines(p, model.report);
    std::ostringstream out;
    grid::write_grdecl(out, model.grid, options);
    return out.str();
}

}  // namespace cutaway::generators::testing

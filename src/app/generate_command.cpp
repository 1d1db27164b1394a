// `cutaway generate --preset NAME | --dims NX NY NZ [options] --seed S --out FILE.grdecl [--deck DIR]`
#include <algorithm>
#include <cctype>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>

#include "app/commands.h"
#include "app_core/option_checks.h"
#include "app/parameter_options.h"
#include "generators/flow_deck_writer.h"
#include "generators/generator.h"
#include "generators/presets.h"
#include "generators/write_progress.h"
#include "grid/grdecl_writer.h"
#include "io/output_batch.h"

namespace cutaway::app {
namespace {

using generators::GeneratorParameters;

struct GenerateOptions {
    std::string preset;
    std::vector<int> dims;
    std::vector<double> extent;
    std::string out;
    std::string deck;
    double memory_limit_gb = default_memory_limit_gib;
    bool quiet = false;
    bool list_presets = false;
    ParameterOverrides<GeneratorParameters> overrides;
};

GeneratorParameters effective_parameters(const GenerateOptions& options) {
    if (options.preset.empty() && options.dims.empty())
        throw std::invalid_argument("--preset: expected a preset NAME or --dims NX NY NZ, found neither");
    GeneratorParameters p = options.preset.empty() ? GeneratorParameters{} : generators::find_preset(options.preset);
    if (options.preset.empty()) p.name = "custom";
    if (!options.dims.empty()) p.dims = {options.dims[0], options.dims[1], options.dims[2]};
    if (!options.extent.empty()) {
        p.length_x = options.extent[0];
        p.length_y = options.extent[1];
        p.thickness = options.extent[2];
    }
    apply_overrides(p, options.overrides);
    return p;
}

/// The deck's case name (flow names its EGRID, INIT and UNRST after it): the preset's name in
/// upper case, "CUSTOM" for --dims models.
std::string deck_case_name(const GeneratorParameters& parameters) {
    std::string name = parameters.name;
    std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return char(std::toupper(c)); });
    return name;
}

int run_generate(const GenerateOptions& options) {
    if (options.list_presets) {
        for (const GeneratorParameters& p : generators::presets())
            std::cout << p.name << ": " << p.dims.nx << " x " << p.dims.ny << " x " << p.dims.nz << " = "
                      << p.dims.cell_count() << " cells\n";
        return 0;
    }
    if (options.out.empty() && options.deck.empty())
        throw std::invalid_argument("--out: expected an output FILE.grdecl (or --deck DIR), found neither");
    const GeneratorParameters parameters = effective_parameters(options);
    const generators::FlowDeckFiles deck_files = generators::flow_deck_files(options.deck, deck_case_name(parameters));
    if (!options.deck.empty())
        refuse_overwrites({}, {{"--deck", deck_files.grid.string()}, {"--deck", deck_files.data.string()},
                               {"--out", options.out}});
    std::ostream* log = options.quiet ? nullptr : &std::cerr;
    generators::ProgressLog progress(log);
    const generators::GeneratedModel model =
        generators::generate_model(parameters, progress, gib_to_bytes(options.memory_limit_gb));
    std::optional<generators::FlowDeckPlan> deck;
    if (!options.deck.empty()) {  // planned before anything is written: a model without room for wells writes nothing
        deck = generators::plan_flow_deck(model.grid);
        progress.finished("deck plan", std::to_string(deck->wells.injectors.size()) + " injectors, " +
                                           std::to_string(deck->wells.producers.size()) + " producers");
    }

    grid::GrdeclWriteOptions write_options;
    write_options.header_comments = generators::header_lines(parameters, model.report);
    if (!options.out.empty())
        io::write_stream(options.out, [&](std::ostream& file) {
            generators::WriteProgressBuf buffer(file.rdbuf(), log);
            std::ostream out(&buffer);
            grid::write_grdecl(out, model.grid, write_options);
            out.flush();
            if (!out) file.setstate(std::ios::badbit);  // the staged file reports the path and reason
            progress.finished("write", std::to_string(buffer.bytes_written()) + " bytes to " + options.out);
        });
    if (deck) {
        generators::write_flow_deck(deck_files, model.grid, *deck, write_options.header_comments);
        progress.finished("deck", deck_files.data.string() + " and " + deck_files.grid.filename().string());
    }
    if (!options.quiet) {
        for (const std::string& line : model.report.lines()) std::cout << line << '\n';
        if (deck)
            for (const std::string& line : generators::describe(*deck)) std::cout << line << '\n';
    }
    return 0;
}

}  // namespace

CommandAction add_generate_command(CLI::App& app) {
    auto options = std::make_shared<GenerateOptions>();
    CLI::App* cmd = app.add_subcommand("generate", "Write a synthetic faulted corner-point model (GRDECL) with PORO, "
                                                   "PERMX, NTG, FACIES and SWAT time steps, and an OPM Flow deck of it");
    cmd->add_option("--preset", options->preset,
                    "zaphirus, petra, opharine, sapphire, scale-1m, scale-10m, scale-100m (options below override it)");
    cmd->add_option("--dims", options->dims, "Cells NX NY NZ")->expected(3);
    cmd->add_option("--extent", options->extent, "Model size east, north and thickness (metres)")->expected(3);
    cmd->add_option("--out", options->out, "Output GRDECL file")->check(writable_output());
    cmd->add_option("--deck", options->deck,
                    "Also write an OPM Flow waterflood deck into DIR (made if missing): NAME.DATA and the grid "
                    "NAME.GRDECL it includes, NAME the preset's in capitals (CUSTOM for --dims); --out is "
                    "optional then")
        ->check(writable_output_directory());
    add_memory_limit_option(*cmd, options->memory_limit_gb, "models");
    cmd->add_flag("--quiet", options->quiet, "No progress lines or report");
    cmd->add_flag("--list-presets", options->list_presets, "Print the presets and exit");
    GenerateOptions& o = *options;
    add_parameter_option(cmd, o.overrides, "--seed", &GeneratorParameters::seed, "Random seed (same seed, same file)");
    add_parameter_option(cmd, o.overrides, "--top-depth", &GeneratorParameters::top_depth, "Mean top depth (metres, z down)");
    add_parameter_option(cmd, o.overrides, "--faults", &GeneratorParameters::fault_count, "Number of fault planes (0..64)");
    add_parameter_option(cmd, o.overrides, "--throw", &GeneratorParameters::throw_range, "Fault throw range MIN MAX (metres)");
    add_parameter_option(cmd, o.overrides, "--dip", &GeneratorParameters::fault_dip_deg, "Fault dip from horizontal (30..90 degrees)");
    add_parameter_option(cmd, o.overrides, "--azimuth", &GeneratorParameters::fault_azimuth_deg, "Mean fault strike (degrees from north)");
    add_parameter_option(cmd, o.overrides, "--azimuth-spread", &GeneratorParameters::fault_azimuth_spread_deg,
                  "Strike spread around the mean (degrees)");
    add_parameter_option(cmd, o.overrides, "--lean-spread", &GeneratorParameters::lean_spread_pillars,
                  "Pillars beside a fault that share its lean");
    add_parameter_option(cmd, o.overrides, "--roughness", &GeneratorParameters::horizon_roughness, "Horizon relief std (metres)");
    add_parameter_option(cmd, o.overrides, "--pinch-fraction", &GeneratorParameters::pinch_out_fraction,
                  "Share of cells pinched out (0..1)");
    add_parameter_option(cmd, o.overrides, "--inactive-fraction", &GeneratorParameters::inactive_fraction,
                  "Share of cells made inactive in clusters (0..1)");
    add_parameter_option(cmd, o.overrides, "--poro-mean", &GeneratorParameters::poro_mean, "Porosity mean (fraction)");
    add_parameter_option(cmd, o.overrides, "--poro-std", &GeneratorParameters::poro_std, "Porosity standard deviation (fraction)");
    add_parameter_option(cmd, o.overrides, "--poro-correlation", &GeneratorParameters::poro_correlation_length,
                  "Porosity lateral correlation length (metres)");
    add_parameter_option(cmd, o.overrides, "--time-steps", &GeneratorParameters::time_steps, "SWAT time steps (0: none)");
    add_parameter_option(cmd, o.overrides, "--injectors", &GeneratorParameters::injector_count, "Injector columns of the water front");
    return [options] { return run_generate(*options); };
}

}  // namespace cutaway::app

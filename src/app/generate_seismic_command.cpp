// `cutaway generate-seismic --preset NAME | --dims NI NX NS [options] --out FILE.sgy`
#include <cerrno>
#include <iostream>
#include <map>
#include <memory>
#include <stdexcept>

#include "app/commands.h"
#include "app_core/option_checks.h"
#include "app/parameter_options.h"
#include "generators/seismic_model.h"
#include "generators/seismic_segy_writer.h"
#include "io/staged_file.h"

namespace cutaway::app {
namespace {

using generators::SeismicParameters;

struct GenerateSeismicOptions {
    std::string preset;
    std::vector<int> dims;
    std::string format = "ieee";
    bool little_endian = false;
    bool crossline_sorted = false;
    bool list_presets = false;
    double memory_limit_gb = default_memory_limit_gib;
    std::string out;
    ParameterOverrides<SeismicParameters> overrides;
};

int format_code(const std::string& name) {
    static const std::map<std::string, int> codes{{"ibm", 1}, {"int32", 2}, {"int16", 3}, {"ieee", 5}, {"int8", 8}};
    const auto it = codes.find(name);
    if (it == codes.end())
        throw std::invalid_argument("--format: expected one of ibm, ieee, int32, int16, int8, found '" + name + "'");
    return it->second;
}

int run_generate_seismic(const GenerateSeismicOptions& options) {
    if (options.list_presets) {
        for (const SeismicParameters& p : generators::seismic_presets())
            std::cout << p.name << ": " << p.inlines << " x " << p.crosslines << " x " << p.samples << '\n';
        return 0;
    }
    if (options.out.empty()) throw std::invalid_argument("--out: expected an output FILE.sgy, found none");
    if (options.preset.empty() && options.dims.empty())
        throw std::invalid_argument("--preset: expected a preset NAME or --dims INLINES CROSSLINES SAMPLES, found neither");
    SeismicParameters p = options.preset.empty() ? SeismicParameters{} : generators::find_seismic_preset(options.preset);
    if (!options.dims.empty()) {
        p.inlines = options.dims[0];
        p.crosslines = options.dims[1];
        p.samples = options.dims[2];
    }
    apply_overrides(p, options.overrides);

    generators::SegyWriteOptions write;
    write.format = format_code(options.format);
    write.little_endian = options.little_endian;
    write.crossline_sorted = options.crossline_sorted;
    const auto volume = generators::generate_seismic(p, gib_to_bytes(options.memory_limit_gb));
    // segyio writes the staged file; a failed write leaves no partial cube under the output name.
    io::StagedFile staged(options.out);
    try {
        generators::write_segy(staged.write_path(), volume, write);
    } catch (const std::runtime_error&) {
        io::fail_output(options.out, errno);  // segyio's failed fwrite/fopen left errno set
    }
    staged.commit();
    std::cout << options.out << ": " << p.name << " " << p.inlines << " x " << p.crosslines << " x " << p.samples
              << " samples, seed " << p.seed << ", format " << options.format << (write.little_endian ? " LSB" : " MSB")
              << (write.crossline_sorted ? ", crossline sorted" : ", inline sorted") << '\n';
    return 0;
}

}  // namespace

CommandAction add_generate_seismic_command(CLI::App& app) {
    auto options = std::make_shared<GenerateSeismicOptions>();
    CLI::App* cmd = app.add_subcommand("generate-seismic",
                                       "Write a synthetic post-stack seismic cube (SEG-Y): layered reflectivity with "
                                       "normal faults, Ricker wavelet, noise");
    cmd->add_option("--preset", options->preset, "paper-500, paper-250, growth-1 .. growth-10 (see --list-presets)");
    cmd->add_option("--dims", options->dims, "INLINES CROSSLINES SAMPLES")->expected(3);
    cmd->add_option("--format", options->format, "Sample format: ibm, ieee (default), int32, int16, int8");
    cmd->add_flag("--little-endian", options->little_endian, "Write little-endian (default big-endian)");
    cmd->add_flag("--crossline-sorted", options->crossline_sorted, "Order traces crossline-major");
    add_memory_limit_option(*cmd, options->memory_limit_gb, "cubes");
    cmd->add_flag("--list-presets", options->list_presets, "Print the presets and exit");
    cmd->add_option("--out", options->out, "Output SEG-Y file")->check(writable_output());
    GenerateSeismicOptions& o = *options;
    add_parameter_option(cmd, o.overrides, "--seed", &SeismicParameters::seed, "Random seed (same seed, same file)");
    add_parameter_option(cmd, o.overrides, "--horizons", &SeismicParameters::horizons, "Reflecting layer boundaries");
    add_parameter_option(cmd, o.overrides, "--faults", &SeismicParameters::faults, "Normal faults (0..16)");
    add_parameter_option(cmd, o.overrides, "--max-throw", &SeismicParameters::max_throw_samples, "Largest fault throw (samples)");
    add_parameter_option(cmd, o.overrides, "--dip", &SeismicParameters::fault_dip_deg, "Fault dip (30..90 degrees)");
    add_parameter_option(cmd, o.overrides, "--relief", &SeismicParameters::horizon_relief_samples, "Horizon undulation (samples)");
    add_parameter_option(cmd, o.overrides, "--ricker-hz", &SeismicParameters::ricker_peak_hz, "Ricker wavelet peak frequency (Hz)");
    add_parameter_option(cmd, o.overrides, "--noise", &SeismicParameters::noise_fraction, "Noise std relative to the signal RMS");
    add_parameter_option(cmd, o.overrides, "--sample-interval-us", &SeismicParameters::sample_interval_us,
                  "Time between samples (microseconds)");
    return [options] { return run_generate_seismic(*options); };
}

}  // namespace cutaway::app

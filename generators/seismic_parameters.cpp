#include "generators/seismic_parameters.h"

#include <cmath>
#include <stdexcept>

#include "generators/parameter_check.h"

namespace cutaway::generators {

namespace {
SeismicParameters sized(std::string name, int inlines, int crosslines, int samples) {
    SeismicParameters p;
    p.name = std::move(name);
    p.inlines = inlines;
    p.crosslines = crosslines;
    p.samples = samples;
    return p;
}

}  // namespace

SeismicParameters growth_step(int step) {
    require_parameter(step >= 1 && step <= 10, "--preset", "growth-1 .. growth-10", "growth-" + std::to_string(step));
    return sized("growth-" + std::to_string(step), 10 * step, 28 * step, 25 * step);
}

std::vector<SeismicParameters> seismic_presets() {
    std::vector<SeismicParameters> presets{sized("paper-500", 101, 101, 500), sized("paper-250", 101, 101, 250)};
    for (int step = 1; step <= 10; ++step) presets.push_back(growth_step(step));
    return presets;
}

SeismicParameters find_seismic_preset(const std::string& name) {
    std::string names;
    for (const SeismicParameters& p : seismic_presets()) {
        if (p.name == name) return p;
        names += (names.empty() ? "" : ", ") + p.name;
    }
    throw std::invalid_argument("--preset: expected one of " + names + ", found '" + name + "'");
}

void validate(const SeismicParameters& p, std::uint64_t memory_limit_bytes) {
    const std::string dims = std::to_string(p.inlines) + " " + std::to_string(p.crosslines) + " " + std::to_string(p.samples);
    require_parameter(p.inlines > 0 && p.crosslines > 0 && p.samples > 1, "--dims",
                      "INLINES CROSSLINES SAMPLES with INLINES, CROSSLINES >= 1 and SAMPLES >= 2", dims);
    require_parameter(p.samples <= 32767, "--dims", "at most 32767 samples (the SEG-Y binary header field is 16-bit)",
                      dims);
    require_parameter(p.sample_interval_us > 0 && p.sample_interval_us <= 32767, "--sample-interval-us",
                      "an integer in [1, 32767] microseconds", p.sample_interval_us);
    require_parameter(p.horizons > 0 && p.horizons <= 10000, "--horizons", "an integer in [1, 10000]", p.horizons);
    require_parameter(p.faults >= 0 && p.faults <= 16, "--faults", "an integer in [0, 16]", p.faults);
    require_parameter(p.max_throw_samples >= 0 && p.max_throw_samples < p.samples, "--max-throw",
                      "a throw in [0, " + std::to_string(p.samples) + ") samples (below the trace length)",
                      p.max_throw_samples);
    require_parameter(p.fault_dip_deg >= 30 && p.fault_dip_deg <= 90, "--dip", "a dip in [30, 90] degrees",
                      p.fault_dip_deg);
    require_parameter(p.horizon_relief_samples >= 0, "--relief", "a relief of at least 0 samples",
                      p.horizon_relief_samples);
    const double nyquist_hz = 0.5e6 / p.sample_interval_us;
    require_parameter(p.ricker_peak_hz > 0 && p.ricker_peak_hz < nyquist_hz, "--ricker-hz",
                      "a frequency in (0, " + parameter_text(nyquist_hz) + ") Hz (below the Nyquist frequency)",
                      p.ricker_peak_hz);
    require_parameter(p.noise_fraction >= 0, "--noise", "a noise level of at least 0", p.noise_fraction);
    const double bytes = double(p.inlines) * double(p.crosslines) * double(p.samples) * sizeof(float);
    const double mib = double(1 << 20);
    require_parameter(bytes <= double(memory_limit_bytes), "--dims",
                      "a cube within the memory limit of " + parameter_text(std::round(double(memory_limit_bytes) / mib)) +
                          " MiB (--memory-limit-gb)",
                      dims + " needing " + parameter_text(std::round(bytes / mib)) + " MiB of samples");
}

}  // namespace cutaway::generators

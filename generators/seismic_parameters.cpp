#include "generators/seismic_parameters.h"

#include <stdexcept>

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

void require(bool ok, const std::string& field, const std::string& expected, double value) {
    if (!ok)
        throw std::invalid_argument("seismic generator: " + field + " = " + std::to_string(value) + ", expected " +
                                    expected);
}
}  // namespace

SeismicParameters growth_step(int step) {
    if (step < 1 || step > 10)
        throw std::invalid_argument("seismic generator: growth step " + std::to_string(step) + ", expected 1..10");
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
    throw std::invalid_argument("seismic generator: no preset '" + name + "' (presets: " + names + ")");
}

void validate(const SeismicParameters& p, std::uint64_t memory_limit_bytes) {
    if (!(p.inlines > 0 && p.crosslines > 0 && p.samples > 1))
        throw std::invalid_argument("seismic generator: dims " + std::to_string(p.inlines) + "x" +
                                    std::to_string(p.crosslines) + "x" + std::to_string(p.samples) +
                                    ", expected inlines, crosslines > 0 and samples > 1");
    require(p.samples <= 32767, "samples", "at most 32767 (SEG-Y binary header field is 16-bit)", p.samples);
    require(p.sample_interval_us > 0 && p.sample_interval_us <= 32767, "sample_interval_us", "1..32767 microseconds",
            p.sample_interval_us);
    require(p.horizons > 0 && p.horizons <= 10000, "horizons", "1..10000", p.horizons);
    require(p.faults >= 0 && p.faults <= 16, "faults", "0..16", p.faults);
    require(p.max_throw_samples >= 0 && p.max_throw_samples < p.samples, "max_throw_samples",
            "0 <= throw < samples", p.max_throw_samples);
    require(p.fault_dip_deg >= 30 && p.fault_dip_deg <= 90, "fault_dip_deg", "30..90 degrees", p.fault_dip_deg);
    require(p.horizon_relief_samples >= 0, "horizon_relief_samples", ">= 0", p.horizon_relief_samples);
    require(p.ricker_peak_hz > 0 && p.ricker_peak_hz < 0.5e6 / p.sample_interval_us, "ricker_peak_hz",
            "0 < f < Nyquist frequency", p.ricker_peak_hz);
    require(p.noise_fraction >= 0, "noise_fraction", ">= 0", p.noise_fraction);
    const double bytes = double(p.inlines) * double(p.crosslines) * double(p.samples) * sizeof(float);
    if (bytes > double(memory_limit_bytes))
        throw std::invalid_argument("seismic generator: " + std::to_string(p.inlines) + "x" +
                                    std::to_string(p.crosslines) + "x" + std::to_string(p.samples) + " needs " +
                                    std::to_string(bytes / double(1 << 20)) +
                                    " MiB of samples, beyond the memory limit of " +
                                    std::to_string(double(memory_limit_bytes) / double(1 << 20)) + " MiB");
}

}  // namespace cutaway::generators

#include "generators/seismic_model.h"

#include <cmath>
#include <numbers>
#include <vector>

#include "generators/deterministic_random.h"

namespace cutaway::generators {

namespace {

// Streams of DeterministicRandom, one per stage, so stages never shift each other's draws.
enum Stream : std::uint64_t { kHorizonStream = 101, kFaultStream = 102, kNoiseStream = 103 };

/// One reflecting boundary: time (samples) = base + relief * sum of two tilted sine waves.
struct Horizon {
    double base_samples = 0;
    double reflection = 0;  ///< reflection coefficient (signed)
    double phase[2] = {0, 0};
    double wave_x[2] = {0, 0};  ///< cycles across the inline range
    double wave_y[2] = {0, 0};  ///< cycles across the crossline range
};

/// Normal fault: map-view line through (px, py) with normal (nx, ny); the side where
/// n.(p - c) - t cot(dip) > 0 (measured in trace spacings, one sample ~ one trace) drops by `throw`.
struct Fault {
    double px = 0, py = 0, nx = 1, ny = 0;
    double throw_samples = 0;
};

std::vector<Horizon> make_horizons(const SeismicParameters& p) {
    DeterministicRandom random(p.seed, kHorizonStream);
    std::vector<Horizon> horizons(std::size_t(p.horizons));
    const double spacing = double(p.samples) / p.horizons;
    for (std::size_t k = 0; k < horizons.size(); ++k) {
        Horizon& h = horizons[k];
        h.base_samples = (double(k) + 0.5) * spacing + random.uniform(-0.3, 0.3) * spacing;
        h.reflection = 0.1 * random.normal();
        for (int w = 0; w < 2; ++w) {
            h.phase[w] = random.uniform(0, 2 * std::numbers::pi);
            h.wave_x[w] = random.uniform(0.2, 1.5);
            h.wave_y[w] = random.uniform(0.2, 1.5);
        }
    }
    return horizons;
}

std::vector<Fault> make_faults(const SeismicParameters& p) {
    DeterministicRandom random(p.seed, kFaultStream);
    std::vector<Fault> faults(std::size_t(p.faults));
    for (Fault& f : faults) {
        const double strike = random.uniform(0, std::numbers::pi);
        f.nx = std::cos(strike);
        f.ny = std::sin(strike);
        f.px = random.uniform(0.2, 0.8) * p.inlines;
        f.py = random.uniform(0.2, 0.8) * p.crosslines;
        f.throw_samples = random.uniform(0.3, 1.0) * p.max_throw_samples;
    }
    return faults;
}

double horizon_time(const Horizon& h, const SeismicParameters& p, int i, int x) {
    const double u = double(i) / p.inlines, v = double(x) / p.crosslines;
    double relief = 0;
    for (int w = 0; w < 2; ++w)
        relief += 0.5 * std::sin(2 * std::numbers::pi * (h.wave_x[w] * u + h.wave_y[w] * v) + h.phase[w]);
    return h.base_samples + p.horizon_relief_samples * relief;
}

/// Horizon time after every fault whose hanging wall holds the point has dropped it.
double faulted_time(double time, const std::vector<Fault>& faults, double cot_dip, int i, int x) {
    for (const Fault& f : faults)
        if (f.nx * (i - f.px) + f.ny * (x - f.py) - time * cot_dip > 0) time += f.throw_samples;
    return time;
}

std::vector<double> ricker_taps(const SeismicParameters& p) {
    const double dt = p.sample_interval_us * 1e-6;
    const int half = int(std::ceil(1.5 / (p.ricker_peak_hz * dt)));
    std::vector<double> taps(std::size_t(2 * half + 1));
    for (int k = -half; k <= half; ++k) taps[std::size_t(k + half)] = ricker(p.ricker_peak_hz, k * dt);
    return taps;
}

}  // namespace

double ricker(double peak_hz, double time_s) {
    const double a = std::numbers::pi * std::numbers::pi * peak_hz * peak_hz * time_s * time_s;
    return (1 - 2 * a) * std::exp(-a);
}

SeismicVolume generate_seismic(const SeismicParameters& p, std::uint64_t memory_limit_bytes) {
    validate(p, memory_limit_bytes);
    const std::vector<Horizon> horizons = make_horizons(p);
    const std::vector<Fault> faults = make_faults(p);
    const std::vector<double> taps = ricker_taps(p);
    const int half = int(taps.size() / 2);
    const double cot_dip = 1.0 / std::tan(p.fault_dip_deg * std::numbers::pi / 180);

    SeismicVolume volume;
    volume.inlines = p.inlines;
    volume.crosslines = p.crosslines;
    volume.samples = p.samples;
    volume.sample_interval_us = p.sample_interval_us;
    volume.amplitudes.assign(volume.trace_count() * std::size_t(p.samples), 0.0f);

    std::vector<double> reflectivity(std::size_t(p.samples));
    double sum_squares = 0;
    for (int i = 0; i < p.inlines; ++i)
        for (int x = 0; x < p.crosslines; ++x) {
            std::fill(reflectivity.begin(), reflectivity.end(), 0.0);
            for (const Horizon& h : horizons) {
                const double t = faulted_time(horizon_time(h, p, i, x), faults, cot_dip, i, x);
                const double lower = std::floor(t), frac = t - lower;  // spike split between two samples
                if (lower >= 0 && lower < p.samples) reflectivity[std::size_t(lower)] += h.reflection * (1 - frac);
                if (lower + 1 >= 0 && lower + 1 < p.samples) reflectivity[std::size_t(lower) + 1] += h.reflection * frac;
            }
            for (int t = 0; t < p.samples; ++t) {
                double trace = 0;
                for (int k = -half; k <= half; ++k)
                    if (t - k >= 0 && t - k < p.samples) trace += taps[std::size_t(k + half)] * reflectivity[std::size_t(t - k)];
                volume.amplitudes[volume.index(i, x, t)] = float(trace);
                sum_squares += trace * trace;
            }
        }

    const double noise_std = p.noise_fraction * std::sqrt(sum_squares / double(volume.amplitudes.size()));
    DeterministicRandom random(p.seed, kNoiseStream);
    for (float& a : volume.amplitudes) a += float(noise_std * random.normal());
    return volume;
}

}  // namespace cutaway::generators

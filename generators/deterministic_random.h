#pragma once
// Random numbers that are the same on every platform and standard library: std::mt19937_64 bits
// turned into values by our own formulas (the std:: distributions are implementation-defined).
#include <cstdint>
#include <random>

namespace cutaway::generators {

class DeterministicRandom {
public:
    /// `seed`: the model seed; `stream`: a fixed id per use, so each stage draws its own sequence
    /// and adding draws to one stage never changes another.
    DeterministicRandom(std::uint64_t seed, std::uint64_t stream);

    /// Uniform in [0, 1), 53 random bits.
    double uniform01();
    /// Uniform in [lo, hi).
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform01(); }
    /// Uniform integer in [0, n), n > 0 (rejection sampling, no modulo bias).
    std::uint64_t below(std::uint64_t n);
    /// Standard normal (Box-Muller, both values used in turn).
    double normal();

private:
    std::mt19937_64 engine_;
    double spare_normal_ = 0;
    bool has_spare_ = false;
};

}  // namespace cutaway::generators

#include "deterministic_random.h"

#include <cmath>
#include <numbers>

namespace cutaway::generators {
namespace {

/// SplitMix64 finaliser: decorrelates nearby (seed, stream) pairs before they seed the engine.
std::uint64_t mix(std::uint64_t x) {
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

}  // namespace

DeterministicRandom::DeterministicRandom(std::uint64_t seed, std::uint64_t stream)
    : engine_(mix(mix(seed) ^ (stream * 0xD1B54A32D192ED03ull))) {}

double DeterministicRandom::uniform01() { return double(engine_() >> 11) * 0x1.0p-53; }

std::uint64_t DeterministicRandom::below(std::uint64_t n) {
    const std::uint64_t limit = ~std::uint64_t(0) - (~std::uint64_t(0) % n);
    std::uint64_t bits = engine_();
    while (bits >= limit) bits = engine_();
    return bits % n;
}

double DeterministicRandom::normal() {
    if (has_spare_) {
        has_spare_ = false;
        return spare_normal_;
    }
    double u1 = uniform01();
    while (u1 <= 0) u1 = uniform01();
    const double u2 = uniform01();
    const double radius = std::sqrt(-2.0 * std::log(u1));
    const double angle = 2.0 * std::numbers::pi * u2;
    spare_normal_ = radius * std::sin(angle);
    has_spare_ = true;
    return radius * std::cos(angle);
}

}  // namespace cutaway::generators

#include "rock_properties.h"

#include <algorithm>
#include <cmath>

#include "smooth_field.h"

namespace cutaway::generators {
namespace {

constexpr double kLayerCorrelation = 0.7;
constexpr double kLayerShiftShare = 0.5;  ///< share of the variance that is a per-layer shift

enum Facies : std::int32_t { shale = 1, sand = 2, clean_sand = 3 };

Facies facies_of(double poro, double mean, double std) {
    if (poro < mean - 0.75 * std) return shale;
    if (poro > mean + 0.75 * std) return clean_sand;
    return sand;
}

/// log10(k / mD) = 1 + 10 (poro - 0.1): 10 mD at 10%, 100 mD at 20%, 1 D at 30%; shale / 10.
double permeability_md(double poro, Facies facies) {
    const double k = std::pow(10.0, 1 + 10 * (poro - 0.1));
    return facies == shale ? 0.1 * k : k;
}

}  // namespace

RockProperties make_rock_properties(const GeneratorParameters& p, const ModelFrame& frame, DeterministicRandom& random) {
    const grid::GridDims& d = p.dims;
    RockProperties rock;
    rock.poro = layered_field(d.nx, d.ny, d.nz, frame.dx, frame.dy, p.poro_correlation_length, kLayerCorrelation,
                              random);
    const double lateral = std::sqrt(1 - kLayerShiftShare * kLayerShiftShare);
    const double upper = std::max(0.45, p.poro_mean + 3 * p.poro_std);
    rock.permx.resize(rock.poro.size());
    rock.ntg.resize(rock.poro.size());
    rock.facies.resize(rock.poro.size());
    std::size_t n = 0;
    for (int k = 0; k < d.nz; ++k) {
        const double shift = kLayerShiftShare * random.normal();
        for (std::size_t c = 0; c < std::size_t(d.nx) * std::size_t(d.ny); ++c, ++n) {
            const double poro = std::clamp(p.poro_mean + p.poro_std * (lateral * rock.poro[n] + shift), 0.01, upper);
            const Facies facies = facies_of(poro, p.poro_mean, p.poro_std);
            rock.poro[n] = float(poro);
            rock.facies[n] = facies;
            rock.permx[n] = float(permeability_md(poro, facies));
            rock.ntg[n] = float(std::clamp((poro - 0.02) / (p.poro_mean + p.poro_std - 0.02), 0.05, 1.0));
        }
    }
    return rock;
}

}  // namespace cutaway::generators

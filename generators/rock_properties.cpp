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

RockProperties make_rock_properties(const GeneratorParameters& p, const ModelFrame& frame, DeterministicRandom& random,
                                    const grid::IjkBox& box) {
    const grid::GridDims& d = p.dims;
    const LayeredField field(d.nx, d.ny, d.nz, frame.dx, frame.dy, p.poro_correlation_length, kLayerCorrelation, random);
    std::vector<double> shifts(std::size_t(d.nz));  // drawn after every layer's lattice
    for (double& shift : shifts) shift = kLayerShiftShare * random.normal();
    const double lateral = std::sqrt(1 - kLayerShiftShare * kLayerShiftShare);
    const double upper = std::max(0.45, p.poro_mean + 3 * p.poro_std);
    RockProperties rock;
    const grid::GridDims b = box.dims();
    const std::size_t cells = b.cell_count();
    rock.poro.resize(cells);
    rock.permx.resize(cells);
    rock.ntg.resize(cells);
    rock.facies.resize(cells);
    // Rows of cells split over the threads; every random number was drawn above.
#pragma omp parallel for collapse(2) schedule(static)
    for (int k = box.k0; k <= box.k1; ++k)
        for (int j = box.j0; j <= box.j1; ++j)
            for (int i = box.i0; i <= box.i1; ++i) {
                const double poro = std::clamp(p.poro_mean + p.poro_std * (lateral * field.at(i, j, k) + shifts[std::size_t(k)]),
                                               0.01, upper);
                const Facies facies = facies_of(poro, p.poro_mean, p.poro_std);
                const std::size_t cell = b.cell_index(i - box.i0, j - box.j0, k - box.k0);
                rock.poro[cell] = float(poro);
                rock.facies[cell] = facies;
                rock.permx[cell] = float(permeability_md(poro, facies));
                rock.ntg[cell] = float(std::clamp((poro - 0.02) / (p.poro_mean + p.poro_std - 0.02), 0.05, 1.0));
            }
    return rock;
}

}  // namespace cutaway::generators

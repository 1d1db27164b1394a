#include "generator.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "cell_validity.h"
#include "faults.h"
#include "horizon_surfaces.h"
#include "layering.h"
#include "pillar_depths.h"
#include "pillar_leans.h"
#include "rock_properties.h"
#include "smooth_field.h"
#include "water_saturation.h"

namespace cutaway::generators {
namespace {

/// Fixed random stream per stage (see DeterministicRandom).
enum RandomStream : std::uint64_t { faults_stream = 1, horizons_stream, layering_stream, inactive_stream,
                                    rock_stream, water_stream };

/// Metres the horizons are sampled beyond the model so leaning pillars still meet them.
double horizon_margin(const GeneratorParameters& p, const ModelFrame& frame, const std::vector<PillarLean>& leans,
                      double total_throw) {
    double lean = 0;
    for (const PillarLean& l : leans) lean = std::max(lean, std::hypot(l.x, l.y));
    const double depth_span = 3 * p.thickness + 10 * p.horizon_roughness + total_throw;
    return lean * depth_span + 2 * std::max(frame.dx, frame.dy);
}

/// COORD of the pillars of `box`: each from above the shallowest to below the deepest faulted horizon.
std::vector<double> make_coord(const ModelFrame& frame, const std::vector<PillarLean>& leans, double top, double bottom,
                               const grid::IjkBox& box) {
    const grid::GridDims& d = frame.dims;
    std::vector<double> coord;
    coord.reserve(box.dims().coord_value_count());
    for (int pj = box.j0; pj <= box.j1 + 1; ++pj)
        for (int pi = box.i0; pi <= box.i1 + 1; ++pi) {
            const PillarLean& lean = leans[d.pillar_index(pi, pj)];
            for (double z : {top, bottom}) {
                coord.push_back(frame.pillar_x(pi) + lean.x * (z - frame.mid_depth));
                coord.push_back(frame.pillar_y(pj) + lean.y * (z - frame.mid_depth));
                coord.push_back(z);
            }
        }
    return coord;
}

grid::Pillar pillar_from_coord(const std::vector<double>& coord, std::size_t pillar) {
    const double* v = &coord[6 * pillar];
    return {{v[0], v[1], v[2]}, {v[3], v[4], v[5]}};
}

/// ACTNUM of the cells of `box` from their shapes (pinched, inverted, degenerate cells are
/// inactive) and the clustered inactive field (its threshold is a quantile over the whole model);
/// counts go into `report`. `coord`: the box's pillars.
std::vector<std::uint8_t> make_actnum(const GeneratorParameters& p, const ModelFrame& frame, const grid::IjkBox& box,
                                      const std::vector<double>& coord, const PillarDepths& depths,
                                      GenerationReport& report) {
    const grid::GridDims& d = p.dims;
    const grid::GridDims b = box.dims();
    DeterministicRandom random(p.seed, inactive_stream);
    const LayeredField cluster(d.nx, d.ny, d.nz, frame.dx, frame.dy, p.poro_correlation_length, 0.8, random);
    const float threshold = p.inactive_fraction > 0 ? quantile(cluster, p.inactive_fraction) : -std::numeric_limits<float>::infinity();
    std::vector<std::uint8_t> actnum(b.cell_count(), 1);
    std::size_t pinched = 0, inverted = 0, degenerate = 0, clustered = 0;
    // Rows of cells split over the threads (CGAL's filtered predicates are thread-safe).
#pragma omp parallel for collapse(2) schedule(static) reduction(+ : pinched, inverted, degenerate, clustered)
    for (int k = box.k0; k <= box.k1; ++k)
        for (int j = box.j0; j <= box.j1; ++j)
            for (int i = box.i0; i <= box.i1; ++i) {
                grid::CellCorners corners;
                for (int c = 0; c < 8; ++c) {
                    const grid::Pillar pillar = pillar_from_coord(coord, b.pillar_index(i - box.i0 + (c & 1), j - box.j0 + (c >> 1 & 1)));
                    corners[std::size_t(c)] = grid::point_on_pillar(pillar, depths.depth(i, j, c & 3, k + (c >> 2)));
                }
                switch (check_cell(corners)) {
                    case CellValidity::pinched: ++pinched; break;
                    case CellValidity::inverted: ++inverted; break;
                    case CellValidity::degenerate: ++degenerate; break;
                    case CellValidity::valid:
                        if (!(cluster.at(i, j, k) < threshold)) continue;
                        ++clustered;
                        break;
                }
                actnum[b.cell_index(i - box.i0, j - box.j0, k - box.k0)] = 0;
            }
    report.pinched_cells += pinched;
    report.inverted_cells += inverted;
    report.degenerate_cells += degenerate;
    report.clustered_inactive += clustered;
    return actnum;
}

/// ZCORN of `box` in Eclipse order straight from the pillar depth columns (no 8-per-cell temporary).
grid::ZcornStore make_zcorn(const grid::IjkBox& box, const PillarDepths& depths) {
    grid::ZcornStore zcorn(box.dims());
    for (int k = box.k0; k <= box.k1; ++k)
        for (int bottom = 0; bottom < 2; ++bottom)
            for (int j = box.j0; j <= box.j1; ++j)
                for (int north = 0; north < 2; ++north)
                    for (int i = box.i0; i <= box.i1; ++i)
                        for (int east = 0; east < 2; ++east) zcorn.push(depths.depth(i, j, east + 2 * north, k + bottom));
    return zcorn;
}

}  // namespace

GeneratedModel generate_block(const GeneratorParameters& p, const grid::IjkBox& box, ProgressLog& progress,
                              std::size_t memory_limit_bytes) {
    validate(p, memory_limit_bytes, box);
    const ModelFrame frame = ModelFrame::from(p);
    GeneratedModel model;
    GenerationReport& report = model.report;
    report.cells = box.dims().cell_count();

    DeterministicRandom fault_random(p.seed, faults_stream);
    const std::vector<FaultPlane> faults = make_faults(p, frame, fault_random);
    const std::vector<std::uint64_t> masks = hanging_wall_masks(faults, frame);
    model.column_offsets = column_offsets(faults, masks);
    double total_throw = 0;
    for (const FaultPlane& f : faults) {
        total_throw += f.throw_m;
        report.faults.push_back(f.describe());
    }
    // Cell corners lie at most this far from mid-depth: half the thickness, every throw, and
    // the horizons' roughness (three standard deviations).
    const double depth_reach = 0.5 * p.thickness + total_throw + 3 * p.horizon_roughness;
    const PillarLeans pillar_lean_field = pillar_leans(frame, faults, masks, p.lean_spread_pillars, depth_reach);
    const std::vector<PillarLean>& leans = pillar_lean_field.leans;
    report.lean_scale = pillar_lean_field.scale;
    progress.finished("faults", std::to_string(faults.size()) + " planes");

    DeterministicRandom layering_random(p.seed, layering_stream);
    const Layering layering(p, frame, layering_random);
    DeterministicRandom horizon_random(p.seed, horizons_stream);
    const HorizonSurfaces horizons(p, frame, layering.zones(), horizon_margin(p, frame, leans, total_throw),
                                   horizon_random);
    report.horizons = horizons.count();
    report.triangles_per_horizon = horizons.triangles_per_horizon();
    progress.finished("horizons", std::to_string(horizons.count()) + " surfaces of " +
                                      std::to_string(horizons.triangles_per_horizon()) + " triangles");

    const PillarDepths depths(frame, horizons, layering, leans, model.column_offsets, box);
    report.repaired_depths = depths.repaired_depths();
    report.depth_columns = depths.variants();
    std::vector<double> coord = make_coord(frame, leans, horizons.min_depth() - 10,
                                           horizons.max_depth() + total_throw + 10, box);
    progress.finished("pillars", std::to_string(depths.variants()) + " depth columns");

    std::vector<std::uint8_t> actnum = make_actnum(p, frame, box, coord, depths, report);
    progress.finished("cell checks");

    grid::ZcornStore zcorn = make_zcorn(box, depths);
    model.grid = grid::CornerPointGrid(box.dims(), std::move(coord), std::move(zcorn), std::move(actnum));
    report.active_cells = model.grid.active_count();
    progress.finished("zcorn");

    DeterministicRandom rock_random(p.seed, rock_stream);
    RockProperties rock = make_rock_properties(p, frame, rock_random, box);
    progress.finished("rock properties");
    model.grid.set_property("PORO", std::move(rock.poro));
    model.grid.set_property("PERMX", std::move(rock.permx));
    model.grid.set_property("NTG", std::move(rock.ntg));
    model.grid.set_int_property("FACIES", std::move(rock.facies));
    return model;
}

GeneratedModel generate_model(const GeneratorParameters& p, ProgressLog& progress, std::size_t memory_limit_bytes) {
    GeneratedModel model = generate_block(p, grid::IjkBox::whole(p.dims), progress, memory_limit_bytes);
    const ModelFrame frame = ModelFrame::from(p);
    DeterministicRandom water_random(p.seed, water_stream);
    WaterFlood flood = make_water_flood(p, frame, p.thickness / p.dims.nz, model.grid.actnum(),
                                        *model.grid.property("PERMX"), water_random);
    for (const grid::CellIjk& c : flood.injectors)
        model.report.injectors.push_back(std::to_string(c.i) + " " + std::to_string(c.j));
    model.report.swept_fraction = flood.swept_fraction;
    for (std::vector<float>& step : flood.steps) model.grid.add_dynamic_step("SWAT", std::move(step));
    progress.finished("water saturation", std::to_string(p.time_steps) + " steps");
    return model;
}

std::vector<std::string> header_lines(const GeneratorParameters& parameters, const GenerationReport& report) {
    std::vector<std::string> lines = describe(parameters);
    lines.push_back("--- what was built ---");
    for (std::string& line : report.lines()) lines.push_back(std::move(line));
    return lines;
}

}  // namespace cutaway::generators

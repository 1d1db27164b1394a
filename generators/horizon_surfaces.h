#pragma once
// Key horizons as triangulated surfaces (CGAL Delaunay_triangulation_2 over jittered sample
// points, copied into a Surface_mesh) with one AABB tree each, so a pillar line meets a horizon
// by one tree query. Horizons are stacked: top (structure + roughness), then one positive
// isopach per zone, so they never cross in the unfaulted frame.
#include <memory>
#include <vector>

#include "deterministic_random.h"
#include "generator_parameters.h"
#include "model_frame.h"

namespace cutaway::generators {

/// A line through (x, y) at the frame's mid-depth, drifting (lean_x, lean_y) metres per metre
/// of depth: one pillar.
struct PillarLine {
    double x = 0;
    double y = 0;
    double lean_x = 0;
    double lean_y = 0;
};

class HorizonSurfaces {
public:
    /// `zones` + 1 horizons sampled over the model extent widened by `margin` metres each side.
    HorizonSurfaces(const GeneratorParameters& parameters, const ModelFrame& frame, int zones, double margin,
                    DeterministicRandom& random);
    ~HorizonSurfaces();
    HorizonSurfaces(const HorizonSurfaces&) = delete;
    HorizonSurfaces& operator=(const HorizonSurfaces&) = delete;

    int count() const;
    std::size_t triangles_per_horizon() const;
    /// Shallowest and deepest sample of any horizon, metres.
    double min_depth() const;
    double max_depth() const;

    /// Depth at which `pillar` meets horizon `h` when the block the pillar bounds has dropped by
    /// `offset` metres (a fault's throw): the pillar is shifted up by `offset`, intersected with
    /// the unfaulted surface, and the offset added back. Throws std::runtime_error if the
    /// pillar misses the surface (it left the sampled extent).
    double depth_on_pillar(int h, const PillarLine& pillar, double offset) const;

    struct Impl;

private:
    std::unique_ptr<Impl> impl_;
};

}  // namespace cutaway::generators

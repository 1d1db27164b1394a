#include "horizon_surfaces.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Projection_traits_xy_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include "smooth_field.h"

namespace cutaway::generators {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using ProjectedTraits = CGAL::Projection_traits_xy_3<Kernel>;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<std::size_t, ProjectedTraits>;
using Delaunay = CGAL::Delaunay_triangulation_2<ProjectedTraits, CGAL::Triangulation_data_structure_2<VertexBase>>;
using Mesh = CGAL::Surface_mesh<Point>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_face_graph_triangle_primitive<Mesh>>>;

/// Most sample points per horizon: keeps the 10M-cell model's trees small.
constexpr double kMaxSamples = 100000;

struct Horizon {
    Mesh mesh;
    std::unique_ptr<Tree> tree;
};

}  // namespace

struct HorizonSurfaces::Impl {
    std::vector<std::unique_ptr<Horizon>> horizons;
    std::size_t triangles = 0;
    double min_depth = 0;
    double max_depth = 0;
    double mid_depth = 0;
};

HorizonSurfaces::HorizonSurfaces(const GeneratorParameters& p, const ModelFrame& frame, int zones, double margin,
                                 DeterministicRandom& random)
    : impl_(std::make_unique<Impl>()) {
    impl_->mid_depth = frame.mid_depth;
    // Jittered lattice of sample points over the widened extent.
    const double width = p.length_x + 2 * margin, height = p.length_y + 2 * margin;
    const double spacing = std::max({frame.dx, frame.dy, std::sqrt(width * height / kMaxSamples)});
    const int count_x = int(std::ceil(width / spacing)) + 1, count_y = int(std::ceil(height / spacing)) + 1;
    std::vector<std::pair<double, double>> samples;
    for (int j = 0; j < count_y; ++j)
        for (int i = 0; i < count_x; ++i) {
            const bool border = i == 0 || j == 0 || i == count_x - 1 || j == count_y - 1;
            const double jitter_x = border ? 0 : random.uniform(-0.3, 0.3) * spacing;
            const double jitter_y = border ? 0 : random.uniform(-0.3, 0.3) * spacing;
            samples.emplace_back(-margin + std::min(i * spacing, width) + jitter_x,
                                 -margin + std::min(j * spacing, height) + jitter_y);
        }

    // Depths: structure (a dome and a regional tilt) + roughness on the top, isopachs below.
    const double relief_length = std::max(p.length_x, p.length_y) / 5;
    SmoothField2D broad(random, width, height, relief_length);
    SmoothField2D fine(random, width, height, relief_length / 4);
    std::vector<SmoothField2D> isopach_fields;
    for (int z = 0; z < zones; ++z) isopach_fields.emplace_back(random, width, height, relief_length);
    std::vector<std::vector<double>> depths(std::size_t(zones + 1), std::vector<double>(samples.size()));
    for (std::size_t s = 0; s < samples.size(); ++s) {
        const auto [x, y] = samples[s];
        const double u = (x - 0.5 * p.length_x) / (0.4 * p.length_x), v = (y - 0.5 * p.length_y) / (0.4 * p.length_y);
        const double structure = -0.5 * p.thickness * std::exp(-(u * u + v * v)) + 0.2 * p.thickness * x / p.length_x;
        const double relief = (broad.at(x + margin, y + margin) + 0.5 * fine.at(x + margin, y + margin)) / std::sqrt(1.25);
        double depth = p.top_depth + structure + p.horizon_roughness * relief;
        depths[0][s] = depth;
        for (int z = 0; z < zones; ++z) {
            const double isopach = std::max(0.2, 1 + 0.25 * isopach_fields[std::size_t(z)].at(x + margin, y + margin));
            depth += p.thickness / zones * isopach;
            depths[std::size_t(z + 1)][s] = depth;
        }
    }

    // One Delaunay triangulation of the sample positions, shared by every horizon.
    std::vector<std::pair<Point, std::size_t>> indexed;
    for (std::size_t s = 0; s < samples.size(); ++s)
        indexed.emplace_back(Point(samples[s].first, samples[s].second, 0), s);
    const Delaunay triangulation(indexed.begin(), indexed.end());

    impl_->min_depth = *std::min_element(depths.front().begin(), depths.front().end());
    impl_->max_depth = *std::max_element(depths.back().begin(), depths.back().end());
    for (const std::vector<double>& z : depths) {
        auto horizon = std::make_unique<Horizon>();
        std::vector<Mesh::Vertex_index> vertex(samples.size());
        for (std::size_t s = 0; s < samples.size(); ++s)
            vertex[s] = horizon->mesh.add_vertex(Point(samples[s].first, samples[s].second, z[s]));
        for (auto face = triangulation.finite_faces_begin(); face != triangulation.finite_faces_end(); ++face)
            horizon->mesh.add_face(vertex[face->vertex(0)->info()], vertex[face->vertex(1)->info()],
                                   vertex[face->vertex(2)->info()]);
        horizon->tree = std::make_unique<Tree>(faces(horizon->mesh).first, faces(horizon->mesh).second, horizon->mesh);
        horizon->tree->build();
        impl_->triangles = horizon->mesh.number_of_faces();
        impl_->horizons.push_back(std::move(horizon));
    }
}

HorizonSurfaces::~HorizonSurfaces() = default;

int HorizonSurfaces::count() const { return int(impl_->horizons.size()); }
std::size_t HorizonSurfaces::triangles_per_horizon() const { return impl_->triangles; }
double HorizonSurfaces::min_depth() const { return impl_->min_depth; }
double HorizonSurfaces::max_depth() const { return impl_->max_depth; }

double HorizonSurfaces::depth_on_pillar(int h, const PillarLine& pillar, double offset) const {
    const double z_top = impl_->min_depth - 1, z_bottom = impl_->max_depth + 1;
    auto shifted = [&](double z) {
        return Point(pillar.x + pillar.lean_x * (z + offset - impl_->mid_depth),
                     pillar.y + pillar.lean_y * (z + offset - impl_->mid_depth), z);
    };
    const Kernel::Segment_3 segment(shifted(z_top), shifted(z_bottom));
    const auto hit = impl_->horizons[std::size_t(h)]->tree->any_intersection(segment);
    if (hit) {
        if (const Point* point = boost::get<Point>(&hit->first)) return point->z() + offset;
        if (const Kernel::Segment_3* along = boost::get<Kernel::Segment_3>(&hit->first))
            return along->source().z() + offset;
    }
    throw std::runtime_error("generate: pillar at (" + std::to_string(pillar.x) + ", " + std::to_string(pillar.y) +
                             ") misses horizon " + std::to_string(h) + " (lean too large for the sampled extent)");
}

}  // namespace cutaway::generators

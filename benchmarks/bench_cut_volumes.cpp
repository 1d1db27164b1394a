// What cut volumes (issue 45) add to the main job's frame: the paper's settings (1% primaries by
// PORO, 9x9 mean filter, SSAO, ray-cast borders) on --preset at --size, with no volume, one box,
// one cylinder, one closed mesh (a sphere read back from an OBJ file through CGAL), 8 and 32
// boxes, and one well (the tube `well:INJ1` cuts around on the deck `cutaway generate --deck`
// writes for the preset), in one run (one renderer, the volume sets swapped between benchmarks).
//   BM_frame/volumes: index into the cases above. Counters: the stages' median fenced times
//   (stage_counters.h), volume_triangles, frame_ms (the median whole frame).
// Target (issue 45): one box or well <= 1.10 x the frame without volumes, 32 boxes <= 1.50 x.
#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app_core/model_source.h"
#include "app_core/option_checks.h"
#include "app_core/render_options.h"
#include "app_core/run_context.h"
#include "bench_cli.h"
#include "cutaway/cutaway_renderer.h"
#include "gl/gl_context.h"
#include "generators/flow_well_placement.h"
#include "gl/shader_library.h"
#include "grid/cell_geometry.h"
#include "metrics/median.h"
#include "stage_counters.h"
#include "volumes/mesh_file.h"
#include "shapes/tube_mesh.h"
#include "volumes/volume_mesh.h"
#include "wells/well_paths.h"

namespace {

using namespace cutaway;

struct Case {
    const char* name;
    std::vector<shapes::TriangleMesh> meshes;
};

grid::Point3 lerp(const grid::Box3& b, double fx, double fy, double fz) {
    return {b.min.x + fx * (b.max.x - b.min.x), b.min.y + fy * (b.max.y - b.min.y), b.min.z + fz * (b.max.z - b.min.z)};
}

/// `n` x `n` boxes less the ones at the middle of the plan (1 for n = 3, 4 for n = 6: 8 and 32
/// boxes), each an eighth of the model across, from above the top down to mid-depth (shafts).
std::vector<shapes::TriangleMesh> box_grid(const grid::Box3& b, int n) {
    std::vector<shapes::TriangleMesh> boxes;
    const double middle = 0.5 * (n - 1);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            if (std::abs(i - middle) < 1 && std::abs(j - middle) < 1) continue;
            const double x = (i + 0.5) / n, y = (j + 0.5) / n;
            boxes.push_back(volumes::box_mesh(lerp(b, x - 0.0625, y - 0.0625, -0.1), lerp(b, x + 0.0625, y + 0.0625, 0.5)));
        }
    return boxes;
}

/// A UV sphere (`rings` x 2 `rings` quads) as an OBJ file, read back as a closed mesh.
shapes::TriangleMesh sphere_from_obj(const grid::Point3& centre, grid::Point3 radii, int rings) {
    const std::filesystem::path file = std::filesystem::temp_directory_path() / "bench_cut_volumes_sphere.obj";
    {
        std::ofstream out(file);
        const double pi = std::acos(-1.0);
        out << "v " << centre.x << ' ' << centre.y << ' ' << centre.z - radii.z << '\n';
        for (int r = 1; r < rings; ++r)
            for (int s = 0; s < 2 * rings; ++s) {
                const double theta = pi * r / rings, phi = pi * s / rings;
                out << "v " << centre.x + radii.x * std::sin(theta) * std::cos(phi) << ' '
                    << centre.y + radii.y * std::sin(theta) * std::sin(phi) << ' ' << centre.z - radii.z * std::cos(theta) << '\n';
            }
        out << "v " << centre.x << ' ' << centre.y << ' ' << centre.z + radii.z << '\n';
        const int ring_size = 2 * rings, last = 2 + (rings - 1) * ring_size;
        const auto at = [&](int r, int s) { return 2 + (r - 1) * ring_size + (s % ring_size); };  // OBJ is 1-based
        for (int s = 0; s < ring_size; ++s) out << "f 1 " << at(1, s + 1) << ' ' << at(1, s) << '\n';
        for (int r = 1; r + 1 < rings; ++r)
            for (int s = 0; s < ring_size; ++s)
                out << "f " << at(r, s) << ' ' << at(r, s + 1) << ' ' << at(r + 1, s + 1) << ' ' << at(r + 1, s) << '\n';
        for (int s = 0; s < ring_size; ++s) out << "f " << last << ' ' << at(rings - 1, s) << ' ' << at(rings - 1, s + 1) << '\n';
    }
    shapes::TriangleMesh mesh = volumes::read_closed_mesh(file.string(), std::size_t(1) << 30);
    std::filesystem::remove(file);
    return mesh;
}

/// The tube `well:INJ1` (default radius) cuts around on the preset's generated deck: its first
/// injector, placed by the geology and completed in every active layer of its column, as the
/// deck's WELSPECS/COMPDAT give it to the renderer.
shapes::TriangleMesh first_injector_tube(const grid::CornerPointGrid& grid, const grid::Box3& bounds) {
    const generators::WellPlacement placement = generators::place_wells(grid);
    if (placement.injectors.empty()) throw std::invalid_argument("the preset's deck has no injector");
    const generators::DeckWell& injector = placement.injectors.front();
    wells::Well well{injector.name, wells::WellKind::injector, "WATER", wells::WellStatus::open, injector.column.i,
                     injector.column.j, {}};
    for (const int k : injector.column.layers) well.connections.push_back({injector.column.i, injector.column.j, k, true});
    // Built as `--cut-volume well:NAME` builds it (the path simplified, the default radius).
    const volumes::WellPaths paths{{well.name, wells::well_path(well, grid, wells::wellhead_level(grid))}};
    const volumes::VolumeBuildContext context{&paths, volumes::default_well_radius(bounds), 0};
    return volumes::build_volume_mesh(volumes::WellVolume{well.name, std::nullopt}, context);
}

std::vector<Case> cases(const grid::CornerPointGrid& grid, const grid::Box3& b) {
    const grid::Point3 centre = lerp(b, 0.5, 0.5, 0.5);
    const double radius = (b.max.x - b.min.x) / 12;
    return {{"none", {}},
            {"box", {volumes::box_mesh(lerp(b, 0.35, 0.35, -0.1), lerp(b, 0.65, 0.65, 0.5))}},
            {"cylinder", {shapes::tube_mesh({lerp(b, 0.5, 0.5, -0.5), centre}, radius, volumes::tube_sides)}},
            {"mesh", {sphere_from_obj(centre, {3 * radius, 3 * radius, 0.4 * (b.max.z - b.min.z)}, 24)}},
            {"boxes_8", box_grid(b, 3)},
            {"boxes_32", box_grid(b, 6)},
            {"well", {first_injector_tube(grid, b)}}};
}

void bm_frame(benchmark::State& state, pipeline::CutawayRenderer& renderer, const std::vector<Case>& all,
              const pipeline::Camera& camera) {
    const Case& c = all.at(std::size_t(state.range(0)));
    renderer.set_cut_volumes(c.meshes);
    const pipeline::FrameSettings settings;  // the paper's: the main job
    renderer.render(settings, camera);       // warm-up: programs compiled, buffers grown
    bench::StageCounters counters;
    std::vector<double> frames;
    for (auto _ : state) {
        const pipeline::FrameTimes times = renderer.render(settings, camera);
        counters.add(bench::sum_by_stage(pipeline::stage_names, times.stages));
        frames.push_back(times.total.wall_ms);
        state.SetIterationTime(times.total.wall_ms / 1000.0);
    }
    counters.set_counters(state);
    state.counters["frame_ms"] = metrics::median(frames);
    state.counters["volume_triangles"] = double(renderer.status().cut_volume_triangles);
    state.counters["volumes"] = double(c.meshes.size());
}

}  // namespace

int main(int argc, char** argv) {
    std::string preset = "sapphire";
    int width = 1920, height = 1080, frames = 7;
    CLI::App flags{"The main job's frame with cut volumes: none, a box, a cylinder, a mesh, 8 and 32 boxes, a well (Google Benchmark)",
                   "bench_cut_volumes"};
    flags.add_option("--preset", preset, "model (preset:NAME)")->check(app::one_of(bench::model_preset_names()));
    bench::add_dims_option(flags, "--size", {&width, &height}, 16, 8192, "WxH", "pixels", "image size");
    flags.add_option("--frames", frames, "timed frames per case (medians)")->check(app::finite_in(1, 1000));
    if (const std::optional<int> exit_code = bench::parse_flags(flags, argc, argv)) return *exit_code;
    try {
        const app::LoadedModel model = app::load_model({"preset:" + preset}, std::size_t(16) << 30);
        const grid::Box3 bounds = grid::grid_bounds(model.grid);
        const std::vector<Case> all = cases(model.grid, bounds);
        const std::unique_ptr<gl::GlContext> context = gl::create_context(gl::ContextOptions{});
        const gl::ShaderLibrary shaders(gl::ShaderLibrary::default_root());
        const app::RenderOptions defaults;
        const app::PropertyChoice property = app::choose_property(model.grid, defaults);
        pipeline::CutawayRenderer renderer(shaders, model.grid, 0.0, width, height);
        renderer.set_colouring(property.values(), property.colour_bar_label());
        renderer.select(grid::range_for_fraction(model.grid, property.values(), property.name, 0.01));
        const pipeline::Camera camera = pipeline::make_orbit_camera(
            renderer.frame(), defaults.camera_pose(), width, height, renderer.status().colour_bar_reserved_width);
        benchmark::AddCustomContext("gl_renderer", gl::gl_renderer());
        benchmark::AddCustomContext("LP_NUM_THREADS", run_context::lp_num_threads());
        benchmark::AddCustomContext("git_revision", run_context::git_revision());
        benchmark::AddCustomContext("preset", preset);
        benchmark::AddCustomContext("size", std::to_string(width) + "x" + std::to_string(height));
        std::string names;
        for (std::size_t i = 0; i < all.size(); ++i) names += (i ? ", " : "") + std::to_string(i) + " = " + all[i].name;
        benchmark::AddCustomContext("volumes", names);
        benchmark::RegisterBenchmark("BM_frame", [&](benchmark::State& s) { bm_frame(s, renderer, all, camera); })
            ->ArgName("volumes")
            ->DenseRange(0, int(all.size()) - 1)
            ->Iterations(frames)->UseManualTime()->Unit(benchmark::kMillisecond);
        benchmark::Initialize(&argc, argv);
        if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
        benchmark::RunSpecifiedBenchmarks();
        benchmark::Shutdown();
    } catch (const std::exception& error) {
        std::cerr << "bench_cut_volumes: " << error.what() << "\n";
        return 1;
    }
    return 0;
}

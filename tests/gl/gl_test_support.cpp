#include "gl_test_support.h"

#include <optional>

#include "generators/generator.h"

namespace cutaway::test {
namespace {

struct Shared {
    std::unique_ptr<gl::GlContext> context;
    std::unique_ptr<gl::ShaderLibrary> shaders;
    std::optional<app::LoadedModel> reek, petra;
};

Shared& shared() {
    static Shared state;  // the test program's one GL context (tests only)
    return state;
}

}  // namespace

void GlEnvironment::SetUp() {
    shared().context = gl::create_context({});
    shared().shaders = std::make_unique<gl::ShaderLibrary>(gl::ShaderLibrary::default_root());
}

void GlEnvironment::TearDown() {
    shared().shaders.reset();
    shared().context.reset();
}

const gl::ShaderLibrary& GlEnvironment::shaders() { return *shared().shaders; }

const grid::CornerPointGrid& reek() {
    if (!shared().reek) {
        const std::string dir = std::string(CUTAWAY_SHARED_DATA) + "/grdecl/reek/";
        shared().reek = app::load_model({dir + "reek_sim_grid.grdecl", dir + "reek_sim_poro.grdecl"}, std::size_t(1) << 32);
    }
    return shared().reek->grid;
}

const grid::CornerPointGrid& petra() {
    if (!shared().petra) shared().petra = app::load_model({"preset:petra"}, std::size_t(1) << 32);
    return shared().petra->grid;
}

grid::CornerPointGrid faulted_model_with_inactive_cells(const grid::GridDims& dims, double inactive_fraction,
                                                        unsigned seed) {
    generators::GeneratorParameters p;
    p.dims = dims;
    p.fault_count = 5;
    p.throw_range = {10, 40};
    p.inactive_fraction = inactive_fraction;
    p.pinch_out_fraction = 0.05;
    p.time_steps = 0;
    p.seed = seed;
    generators::ProgressLog quiet(nullptr);
    return generators::generate_model(p, quiet).grid;
}

std::unique_ptr<pipeline::CutawayRenderer> make_renderer(const grid::CornerPointGrid& grid, int width, int height) {
    auto renderer = std::make_unique<pipeline::CutawayRenderer>(GlEnvironment::shaders(), grid, 0.0, width, height);
    const std::vector<float>& poro = *grid.property("PORO");
    const grid::PrimaryRange range = grid::active_value_range(grid, poro, "PORO");
    renderer->set_colouring(poro, {"PORO", range.min, range.max, "frac"});
    return renderer;
}

std::vector<std::uint8_t> random_primaries(const grid::CornerPointGrid& grid, std::mt19937& random) {
    const std::vector<float>& poro = *grid.property("PORO");
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (;;) {
        grid::PrimaryRange range;
        if (unit(random) < 0.5) {
            range = grid::range_for_fraction(grid, poro, "PORO", 0.002 + 0.048 * unit(random));
        } else {
            const grid::PrimaryRange all = grid::active_value_range(grid, poro, "PORO");
            const float lo = all.min + float(unit(random)) * (all.max - all.min);
            range = {lo, lo + 0.1f * (all.max - all.min)};
        }
        std::optional<grid::IjkBox> box;
        if (unit(random) < 0.3) {
            const grid::GridDims& d = grid.dims();
            auto pick = [&](int n) {
                std::uniform_int_distribution<int> at(0, n - 1);
                int a = at(random), b = at(random);
                return std::pair{std::min(a, b), std::max(a, b)};
            };
            const auto [i0, i1] = pick(d.nx);
            const auto [j0, j1] = pick(d.ny);
            const auto [k0, k1] = pick(d.nz);
            box = grid::IjkBox{i0, j0, k0, i1, j1, k1};
        }
        std::vector<std::uint8_t> flags = grid::select_primaries(grid, poro, "PORO", range, box);
        if (grid::count_primaries(flags) > 0) return flags;
    }
}

pipeline::OrbitPose random_pose(std::mt19937& random) {
    std::uniform_real_distribution<float> azimuth(0.0f, 360.0f), elevation(5.0f, 85.0f);
    return {azimuth(random), elevation(random), 0.0f, glm::vec3(0)};
}

pipeline::FrameSettings invariant_settings(std::mt19937& random) {
    std::uniform_real_distribution<float> aperture(0.0f, 180.0f);  // full opening angles
    pipeline::FrameSettings settings;
    settings.aperture_h_deg = aperture(random);
    settings.aperture_v_deg = aperture(random);
    settings.mean_filter = 0;
    settings.ssao = false;
    settings.colour_bar = false;
    return settings;
}

}  // namespace cutaway::test

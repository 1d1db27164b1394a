// The distributed frame against the single-process frame (SPEC.md section 7), run under
// `mpirun -np 2` and `-np 4`: every rank draws its K slab (distributed::RankRenderer), rank 0 also
// renders the whole model alone, and on 10 random cameras, selections, apertures and cut strategies
// (frustum, jfa, chamfer-34, frustum-sweep) per model the
// composited cell-id image must equal the single-process one except at pixels explained as ties:
//   - the single-process depth test itself is a tie there: drawing the frame again with ties going
//     to the last-drawn fragment (GL_LEQUAL) shows the distributed frame's cell; or
//   - coincident faces: both frames show a surface at the same depth (within 2e-5 relative, the
//     VisibleDrawIdentity tolerance: the same corners, interpolation rounding). On a rank boundary
//     the two cells sharing a face are drawn by different ranks, and IceT keeps one of the equal
//     depths where one renderer's depth test kept the other.
// With SSAO off the final colour must be equal too wherever the cells are (colour is a function of
// the pixel's cell, face and the global cut), except within 2 pixels of a tie pixel (border and
// contour tests read neighbours).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <random>

#include "annotation/property_units.h"
#include "cutaway/cut_surface/cut_strategy_choice.h"
#include "cutaway/renderer_readback.h"
#include "distributed/rank_blocks.h"
#include "distributed/rank_renderer.h"
#include "generators/generator.h"
#include "generators/presets.h"
#include "gl_test_support.h"
#include "grid/face_classification.h"
#include "mpi_test_support.h"

namespace cutaway::test {
namespace {

constexpr int width = 400, height = 225;  // reduced frames: 4 ranks share 2 cores in CI
constexpr int cameras = 10;
constexpr double tie_relative_depth = 2e-5;
constexpr const char* strategies[] = {"frustum", "jfa", "frustum", "chamfer-34", "frustum-sweep"};

struct Frame {
    std::vector<std::uint32_t> cells;  ///< whole-model Eclipse id + 1, rows bottom to top
    std::vector<float> depth;          ///< linear depth, rows bottom to top
    gl::RgbaImage image;               ///< rows top to bottom
};

Frame single_frame(pipeline::CutawayRenderer& renderer, const pipeline::FrameSettings& settings, const pipeline::Camera& camera) {
    renderer.render(settings, camera);
    return {pipeline::FrameReadback(renderer).read_eclipse_ids(), pipeline::RendererProbe(renderer).read_scene_depth().values, pipeline::FrameReadback(renderer).read_image()};
}

struct Tally {
    std::size_t pixels = 0, differing = 0, order_ties = 0, coincident = 0, unexplained = 0;
    std::size_t colour_compared = 0, colour_differing = 0, colour_unexplained = 0;
};

/// Colour pixels that differ away from any pixel whose cell differs (within 2 pixels).
void compare_colour(const Frame& single, const Frame& distributed, const std::vector<std::uint8_t>& tie, Tally& tally) {
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            ++tally.colour_compared;
            if (std::equal(single.image.at(x, y), single.image.at(x, y) + 3, distributed.image.at(x, y))) continue;
            ++tally.colour_differing;
            bool near_tie = false;
            const int row = height - 1 - y;  // the id images run bottom to top
            for (int dy = -2; dy <= 2 && !near_tie; ++dy)
                for (int dx = -2; dx <= 2 && !near_tie; ++dx) {
                    const int xx = x + dx, yy = row + dy;
                    near_tie = xx >= 0 && yy >= 0 && xx < width && yy < height && tie[std::size_t(yy) * width + std::size_t(xx)];
                }
            if (!near_tie) {
                ++tally.colour_unexplained;
                if (tally.colour_unexplained <= 5)
                    std::cout << "  colour differs away from ties at " << x << "," << y << "\n";
            }
        }
}

/// This rank's renderer of its k slab of `grid`, coloured by PORO over its whole range.
std::unique_ptr<distributed::RankRenderer> make_rank(const grid::CornerPointGrid& grid, const pipeline::ModelFrame& frame) {
    const distributed::MpiSession& session = mpi();
    const grid::IjkBox slab =
        distributed::split_into_slabs(grid, session.size(), distributed::SlabAxis::k)[std::size_t(session.rank())];
    auto rank = std::make_unique<distributed::RankRenderer>(GlEnvironment::shaders(), grid, frame, slab,
                                                            grid::default_face_tolerance(grid), width, height);
    const std::vector<float>& poro = *grid.property("PORO");
    const grid::PrimaryRange range = grid::active_value_range(grid, poro, "PORO");
    rank->set_colouring(poro, {"PORO", range.min, range.max, annotation::property_unit("PORO")});
    return rank;
}

void check_identity(const grid::CornerPointGrid& grid, unsigned seed) {
    const distributed::MpiSession& session = mpi();
    const pipeline::ModelFrame frame = pipeline::make_model_frame(grid, 0.0);
    std::unique_ptr<distributed::RankRenderer> rank_renderer = make_rank(grid, frame);
    distributed::RankRenderer& rank = *rank_renderer;
    std::unique_ptr<pipeline::CutawayRenderer> single;
    if (session.root()) single = make_renderer(grid, width, height);

    std::mt19937 random(seed);  // the same draws on every rank
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    Tally tally;
    for (int trial = 0; trial < cameras; ++trial) {
        SCOPED_TRACE("trial " + std::to_string(trial));
        const std::vector<std::uint8_t> flags = random_primaries(grid, random);
        pipeline::OrbitPose pose = random_pose(random);
        if (trial % 3 == 2) pose.distance = frame.radius() * (1.2f + 1.5f * unit(random));
        const pipeline::Camera camera = pipeline::make_orbit_camera(frame, pose, width, height);
        pipeline::FrameSettings settings = invariant_settings(random);
        // Per-cell frustums (their union is a max of the ranks' cuts) and the cone-field strategies
        // (their seeds are max-reduced, then every rank runs the same transform). Not
        // frustum-clusters: its clusters are built per slab, so its cut differs on purpose.
        settings.strategy = strategies[std::size_t(trial) % std::size(strategies)];
        if (trial % 4 == 3) settings.mean_filter = 9;
        if (trial % 5 == 4) settings.ssao = true;

        rank.set_primaries(flags);
        rank.render(settings, camera);
        if (!session.root()) continue;
        const Frame distributed{rank.composited_ids(), pipeline::RendererProbe(rank.renderer()).read_scene_depth().values, pipeline::FrameReadback(rank.renderer()).read_image()};
        single->select(flags);
        const Frame first = single_frame(*single, settings, camera);
        pipeline::FrameSettings last_wins = settings;
        last_wins.depth_ties_to_last = true;
        const Frame last = single_frame(*single, last_wins, camera);

        std::vector<std::uint8_t> tie(first.cells.size(), 0);
        for (std::size_t p = 0; p < first.cells.size(); ++p) {
            ++tally.pixels;
            if (first.cells[p] == distributed.cells[p]) continue;
            ++tally.differing;
            tie[p] = 1;
            const double a = first.depth[p], d = distributed.depth[p];
            if (distributed.cells[p] == last.cells[p]) {
                ++tally.order_ties;
                continue;
            }
            if (first.cells[p] != 0 && distributed.cells[p] != 0 && std::abs(a - d) <= tie_relative_depth * std::abs(a)) {
                ++tally.coincident;
                continue;
            }
            if (++tally.unexplained <= 10)
                std::cout << "  not a tie: trial " << trial << " pixel " << p % width << "," << p / width
                          << ": single-process cell " << first.cells[p] << " at depth " << a << ", distributed cell "
                          << distributed.cells[p] << " at depth " << d << "\n";
        }
        if (!settings.ssao) compare_colour(first, distributed, tie, tally);
    }
    if (!session.root()) return;
    EXPECT_EQ(tally.unexplained, 0u) << tally.unexplained << " pixels differ by more than a tie";
    EXPECT_LE(double(tally.differing), 0.005 * double(tally.pixels)) << tally.differing << " of " << tally.pixels;
    EXPECT_EQ(tally.colour_unexplained, 0u) << tally.colour_unexplained << " colour pixels differ away from any tie";
    std::cout << "  " << session.size() << " ranks: " << tally.differing << " of " << tally.pixels
              << " cell pixels differ: " << tally.order_ties << " depth-test ties in the single-process frame, "
              << tally.coincident << " coincident faces, " << tally.unexplained << " not ties; colour: "
              << tally.colour_differing << " of " << tally.colour_compared << " differ, " << tally.colour_unexplained
              << " away from ties\n";
}

TEST(DistributedIdentity, Petra) { check_identity(petra(), 21); }

TEST(DistributedIdentity, Sapphire) {
    generators::ProgressLog quiet(nullptr);
    check_identity(generators::generate_model(generators::find_preset("sapphire"), quiet).grid, 22);
}

TEST(DistributedIdentity, FaultedGeneratedModelWithInactiveCells) {
    const grid::CornerPointGrid grid = faulted_model_with_inactive_cells({24, 20, 8}, 0.25, 5);
    ASSERT_LT(grid.active_count(), grid.cell_count());
    check_identity(grid, 23);
}

TEST(DistributedAuto, PicksByThePrimariesOfAllRanks) {
    // "auto" (cut_strategy_choice.h) picks by the primaries of every rank. With 1.2 times the
    // device's threshold of petra's cells selected (600 on llvmpipe, 12,000 on a GPU), over it in
    // all and fewer on at least one rank's slab, every
    // rank must draw frustum-sweep as one process would: a rank picking by its own count would
    // draw frustum-clusters, and the composite would mix two different cuts.
    const distributed::MpiSession& session = mpi();
    const grid::CornerPointGrid& grid = petra();
    const pipeline::ModelFrame frame = pipeline::make_model_frame(grid, 0.0);
    std::unique_ptr<distributed::RankRenderer> rank_renderer = make_rank(grid, frame);
    distributed::RankRenderer& rank = *rank_renderer;
    const std::vector<float>& poro = *grid.property("PORO");
    const double fraction = 1.2 * double(pipeline::auto_sweep_from_primaries(gl::gl_renderer())) / double(grid.active_count());
    rank.set_primaries(grid::select_primaries(grid, poro, "PORO", grid::range_for_fraction(grid, poro, "PORO", fraction)));
    pipeline::FrameSettings settings;
    ASSERT_EQ(settings.strategy, pipeline::auto_cut_strategy);
    std::mt19937 random(31);
    rank.render(settings, pipeline::make_orbit_camera(frame, random_pose(random), width, height));

    const std::uint64_t own = rank.renderer().status().primary_cells;
    const std::uint64_t sweep_from = rank.renderer().status().auto_sweep_from;
    ASSERT_GE(session.sum(own), sweep_from);
    ASSERT_GE(session.sum(own < sweep_from ? 1u : 0u), 1u) << "no rank would pick alone";
    EXPECT_EQ(rank.renderer().status(settings).cut_strategy, "frustum-sweep") << "rank " << session.rank() << ", " << own
                                                                        << " primaries of its own";
}

}  // namespace
}  // namespace cutaway::test

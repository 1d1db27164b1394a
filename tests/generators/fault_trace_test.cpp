// On an untilted model (vertical faults, vertical pillars) the grid core's face classification
// finds fault faces exactly where two columns of different fault blocks meet, and nowhere else.
#include <gtest/gtest.h>

#include "generator_test_support.h"
#include "grid/cell_geometry.h"
#include "grid/face_classification.h"

namespace cutaway::generators {
namespace {

using grid::FaceClass;
using grid::FaceSide;

class UntiltedFaultTraces : public ::testing::TestWithParam<std::uint64_t> {};

TEST_P(UntiltedFaultTraces, FaultFacesExactlyOnTraces) {
    GeneratorParameters p = testing::small_parameters();
    p.seed = GetParam();
    p.fault_dip_deg = 90;
    p.fault_count = 4;
    const GeneratedModel model = testing::generate_quietly(p);
    const grid::CornerPointGrid& g = model.grid;
    const grid::GridDims& d = g.dims();

    for (std::size_t n = 0; n < g.coord().size(); n += 6) {
        ASSERT_EQ(g.coord()[n], g.coord()[n + 3]) << "pillar " << n / 6 << " leans in x";
        ASSERT_EQ(g.coord()[n + 1], g.coord()[n + 4]) << "pillar " << n / 6 << " leans in y";
    }

    const grid::FaceClassification faces(g, grid::default_face_tolerance(g));
    auto offset = [&](int i, int j) { return model.column_offsets[std::size_t(j) * std::size_t(d.nx) + std::size_t(i)]; };
    std::size_t trace_faces = 0, checked = 0;
    for (int k = 0; k < d.nz; ++k)
        for (int j = 0; j < d.ny; ++j)
            for (int i = 0; i < d.nx; ++i) {
                const std::size_t cell = d.cell_index(i, j, k);
                if (!g.active(cell)) continue;
                struct Neighbour { int di, dj, dk; FaceSide side; };
                for (const Neighbour& n : {Neighbour{1, 0, 0, FaceSide::i_plus}, Neighbour{0, 1, 0, FaceSide::j_plus},
                                           Neighbour{0, 0, 1, FaceSide::k_plus}}) {
                    if (!d.contains(i + n.di, j + n.dj, k + n.dk)) continue;
                    if (!g.active(d.cell_index(i + n.di, j + n.dj, k + n.dk))) continue;
                    const bool on_trace = offset(i, j) != offset(i + n.di, j + n.dj);
                    trace_faces += on_trace;
                    ++checked;
                    EXPECT_EQ(faces.at(cell, n.side), on_trace ? FaceClass::fault : FaceClass::interior)
                        << "cell (" << i << "," << j << "," << k << ") side " << int(n.side);
                }
            }
    EXPECT_GT(trace_faces, 20u) << "the faults should cross the model";
    EXPECT_EQ(faces.counts().fault, trace_faces);
    EXPECT_GT(checked, 5000u);
}

INSTANTIATE_TEST_SUITE_P(Seeds, UntiltedFaultTraces, ::testing::Values(1u, 2u, 3u, 17u));

TEST(TiltedFaults, PillarsOnTracesLeanAndCellsStayValid) {
    const GeneratedModel model = testing::generate_quietly(testing::small_parameters());
    const grid::CornerPointGrid& g = model.grid;
    std::size_t leaning = 0;
    for (std::size_t n = 0; n < g.coord().size(); n += 6)
        leaning += g.coord()[n] != g.coord()[n + 3] || g.coord()[n + 1] != g.coord()[n + 4];
    EXPECT_GT(leaning, 10u);
    const grid::GridDims& d = g.dims();
    for (int k = 0; k < d.nz; ++k)
        for (int j = 0; j < d.ny; ++j)
            for (int i = 0; i < d.nx; ++i) {
                if (!g.active(d.cell_index(i, j, k))) continue;
                EXPECT_EQ(grid::classify_shape(g, i, j, k, 0.0), grid::CellShape::regular);
                EXPECT_GT(grid::signed_volume(grid::cell_corners(g, i, j, k)), 0.0);
            }
}

}  // namespace
}  // namespace cutaway::generators

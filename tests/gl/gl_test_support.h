#pragma once
// Shared set-up of the GL tests: one headless context per test program, the shader library, the
// models the tests render (Reek from ../shared/data, a generated preset), random selections.
#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <string>

#include "app_core/model_source.h"
#include "cutaway/cutaway_renderer.h"
#include "gl/gl_context.h"
#include "grid/primary_selection.h"

namespace cutaway::test {

/// The context lives as long as the test program (GTest environment).
class GlEnvironment : public ::testing::Environment {
public:
    void SetUp() override;
    void TearDown() override;
    static const gl::ShaderLibrary& shaders();
};

/// Reek grid + PORO (35,838 active cells), loaded once.
const grid::CornerPointGrid& reek();
/// The petra preset (39 x 42 x 20, generated in memory), once.
const grid::CornerPointGrid& petra();

/// A generated model with faults, pinch-outs and `inactive_fraction` of its cells inactive.
grid::CornerPointGrid faulted_model_with_inactive_cells(const grid::GridDims& dims, double inactive_fraction,
                                                        unsigned seed);

/// A renderer of `grid` coloured by PORO, no colour bar needed by the invariants.
std::unique_ptr<pipeline::CutawayRenderer> make_renderer(const grid::CornerPointGrid& grid, int width, int height);

/// Random primaries: either the top fraction (0.2% to 5%) of PORO or a PORO window, sometimes
/// restricted to a random IJK box. Never empty.
std::vector<std::uint8_t> random_primaries(const grid::CornerPointGrid& grid, std::mt19937& random);

/// Random orbit pose: azimuth 0..360, elevation 5..85 degrees, framed distance.
pipeline::OrbitPose random_pose(std::mt19937& random);

/// Settings of the invariant tests: random apertures, mean filter off, SSAO off (speed).
pipeline::FrameSettings invariant_settings(std::mt19937& random);

}  // namespace cutaway::test

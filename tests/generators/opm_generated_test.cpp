// OPM's EclipseGrid (libopm-common-dev 2022.10) reads every paper preset the generator writes
// with our reader's active count and cell volumes. The file is handed to OPM the way
// tests/opm/opm_reference_test.cpp does: "GRID / INCLUDE 'file' /" (a bare GRDECL's ACTNUM is
// ignored by OPM otherwise), with a parse context that lets the non-GRID keywords (FACIES,
// SWAT) through as warnings.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <opm/input/eclipse/Deck/Deck.hpp>
#include <opm/input/eclipse/EclipseState/Grid/EclipseGrid.hpp>
#include <opm/input/eclipse/Parser/ErrorGuard.hpp>
#include <opm/input/eclipse/Parser/InputErrorAction.hpp>
#include <opm/input/eclipse/Parser/ParseContext.hpp>
#include <opm/input/eclipse/Parser/Parser.hpp>

#include "generator_test_support.h"
#include "opm_grid_loader.h"
#include "grid/cell_geometry.h"
#include "grid/grdecl_reader.h"

namespace cutaway::generators {
namespace {

using cutaway::test::opm_grid;

namespace fs = std::filesystem;

constexpr double kVolumeRelTol = 1e-6;  // relative to OPM's volume: both compute the exact trilinear volume


class OpmReadsPreset : public ::testing::TestWithParam<const char*> {};

TEST_P(OpmReadsPreset, SameActiveCountAndVolumes) {
    const GeneratorParameters p = find_preset(GetParam());
    // The process id in the name: test runs of other checkouts on the machine use the same temp folder.
    const fs::path path =
        fs::temp_directory_path() / ("cutaway_opm_" + std::string(GetParam()) + "_" + std::to_string(::getpid()) + ".grdecl");
    {
        std::ofstream out(path, std::ios::binary);
        out << testing::grdecl_text(p);
    }
    const grid::CornerPointGrid ours = grid::load_grdecl({path});
    const Opm::EclipseGrid opm = opm_grid(path);
    fs::remove(path);

    ASSERT_EQ(opm.getNX(), std::size_t(p.dims.nx));
    ASSERT_EQ(opm.getNY(), std::size_t(p.dims.ny));
    ASSERT_EQ(opm.getNZ(), std::size_t(p.dims.nz));
    ASSERT_EQ(opm.getNumActive(), ours.active_count());
    const grid::GridDims& d = ours.dims();
    double worst = 0;
    for (std::size_t g = 0; g < ours.cell_count(); ++g) {
        ASSERT_EQ(opm.cellActive(g), ours.active(g)) << "ACTNUM differs at cell " << g;
        if (!ours.active(g)) continue;
        const grid::CellIjk c = grid::cell_ijk(d, g);
        const double mine = grid::cell_volume(grid::cell_corners(ours, c.i, c.j, c.k));
        const double theirs = opm.getCellVolume(g);
        worst = std::max(worst, std::abs(mine - theirs) / theirs);
        ASSERT_NEAR(mine, theirs, kVolumeRelTol * theirs) << "cell (" << c.i << "," << c.j << "," << c.k << ")";
    }
    char worst_text[32];
    std::snprintf(worst_text, sizeof worst_text, "%.3e", worst);
    RecordProperty("worst_volume_relative_difference", worst_text);
}

INSTANTIATE_TEST_SUITE_P(Paper, OpmReadsPreset, ::testing::Values("zaphirus", "petra", "opharine", "sapphire"),
                         [](const ::testing::TestParamInfo<const char*>& info) { return std::string(info.param); });

// The 1M-cell scale preset too (7 s in release); 10M needs minutes and many GB in OPM, so it is
// not part of the suite.
INSTANTIATE_TEST_SUITE_P(Scale, OpmReadsPreset, ::testing::Values("scale-1m"),
                         [](const ::testing::TestParamInfo<const char*>& info) {
                             std::string name = info.param;
                             std::replace(name.begin(), name.end(), '-', '_');  // gtest names: [A-Za-z0-9_]
                             return name;
                         });

}  // namespace
}  // namespace cutaway::generators

// Reference test: our GRDECL reader and cell geometry against OPM's EclipseGrid
// (libopm-common-dev 2022.10) on every real GRDECL file in shared/data/grdecl/.
//
// What OPM does, found with a probe program and read from opm-common's EclipseGrid.cpp /
// calculateCellVol.cpp, and pinned down by the tests below:
//
// * Pillar point (EclipseGrid::getCellCorners): for a pillar with top (xt, yt, zt) and bottom
//   (xb, yb, zb) the corner at depth Z is
//       x = xt + (xb - xt) / (zt - zb) * (zt - Z),   y likewise,
//   and when zt == zb (exactly) the corner is (xt, yt, Z): vertical through the top point.
//   That is our point_on_pillar (t = (Z - zt) / (zb - zt)); the two differ only in rounding.
// * Volume (calculateCellVol, Pointing 1989): the exact volume of the trilinear hexahedron,
//   returned as std::fabs(volume). getCellVolume therefore never reports a sign: a left-handed
//   or inverted cell gets a positive volume, like our cell_volume = |signed_volume|.
// * Centre (getCellCenter): the mean of the 8 corners, like our cell_centre.
// * fixupZCORN (ZcornMapper::fixupZCORN, run by every EclipseGrid constructor): with
//   sign = +1 if ZCORN(0,0,0,corner 0) <= ZCORN(0,0,NZ-1,corner 4) else -1, for k, j, i and each
//   of the 4 pillar corners c, in that order:
//     1. cell to cell: if k > 0 and (top(k, c) - bottom(k-1, c)) * sign < 0, then
//        top(k, c) = bottom(k-1, c)          (a layer overlapping the one above is cut)
//     2. in cell:      if (bottom(k, c) - top(k, c)) * sign < 0, then
//        bottom(k, c) = top(k, c)            (a crossed pillar edge is collapsed)
//   OPM's geometry is computed from the repaired ZCORN. Our reader keeps ZCORN as written and
//   reports instead: classify_shape() flags rule-2 cells (bottom above top in the file) as
//   CellShape::inverted, overlaps_layer_above() flags rule-1 cells (a top above the bottom of the
//   layer above in the file); `cutaway inspect` counts both. Their volumes are the file's.
//   On the shared data OPM changes exactly one value: sixcells2_described_zoverlap.grdecl,
//   cell (0,0,1) (global 2) corner 1, top 690 -> 710 (rule 1), which we flag as overlapping.
//   No file has a rule-2 cell, and we flag no cell as inverted. Repaired cells are compared
//   separately (see the test). Direction: both take `sign` from the data the same way
//   (CornerPointGrid::depth_direction), so a grid whose depths decrease with k is left alone by
//   OPM and flagged nowhere by us (OpmSemantics.DepthDecreasingWithK).
// * MAPAXES / GRIDUNIT METRES: neither side applies MAPAXES to cell geometry; OPM's corners and
//   centres are in the COORD frame, like ours (reek has MAPAXES and matches).
// * ACTNUM: OPM 2022.10's EclipseGrid(const Deck&) takes ACTNUM through FieldProps, which only
//   scans the GRID section. A bare GRDECL file has no section keywords, so its ACTNUM is
//   silently ignored (reek: 35,840 active instead of 35,838). We therefore hand OPM the file the
//   way a simulator deck does: "GRID / INCLUDE 'file' /".
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <ostream>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <opm/common/utility/numeric/calculateCellVol.hpp>
#include <opm/input/eclipse/Deck/Deck.hpp>
#include <opm/input/eclipse/Deck/DeckKeyword.hpp>
#include <opm/input/eclipse/EclipseState/Grid/EclipseGrid.hpp>
#include <opm/input/eclipse/Parser/ErrorGuard.hpp>
#include <opm/input/eclipse/Parser/InputErrorAction.hpp>
#include <opm/input/eclipse/Parser/ParseContext.hpp>
#include <opm/input/eclipse/Parser/Parser.hpp>

#include "grid/cell_geometry.h"
#include "grid/corner_point_grid.h"
#include "grid/grdecl_reader.h"
#include "grid/zcorn_store.h"
#include "opm_grid_loader.h"


namespace {

namespace fs = std::filesystem;
using namespace cutaway::grid;
using cutaway::test::lenient_parse_context;
using cutaway::test::opm_grid;

const fs::path kGrdeclDir = fs::path(CUTAWAY_SHARED_DATA) / "grdecl";

constexpr double kVolumeRelTol = 1e-6;  // relative to OPM's volume
constexpr double kCentreRelTol = 1e-6;  // relative to the active cells' bounding-box diagonal

// ---------------------------------------------------------------------------------------------
// The shared files.

std::string read_text(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

/// A file that defines a grid (SPECGRID or DIMENS at the start of a line), as opposed to a
/// property-only file such as reek_sim_poro.grdecl.
bool is_grid_file(const fs::path& path) {
    std::istringstream lines(read_text(path));
    for (std::string line; std::getline(lines, line);)
        if (line.rfind("SPECGRID", 0) == 0 || line.rfind("DIMENS", 0) == 0) return true;
    return false;
}

struct GridCase {
    fs::path grid_file;
    std::vector<fs::path> our_files;  ///< grid file first, then its property files
    std::string name;                 ///< test-name-safe
};

void PrintTo(const GridCase& c, std::ostream* os) { *os << c.grid_file.string(); }

/// Every grid file under shared/data/grdecl/. A grid file named `<prefix>grid.grdecl` is read by
/// our reader together with the property-only files `<prefix>*.grdecl` beside it
/// (reek_sim_grid.grdecl + reek_sim_poro.grdecl); OPM only gets the grid file.
std::vector<GridCase> discover_cases() {
    std::vector<GridCase> cases;
    if (!fs::is_directory(kGrdeclDir)) return cases;
    std::vector<fs::path> files;
    for (const auto& entry : fs::recursive_directory_iterator(kGrdeclDir))
        if (entry.is_regular_file() && entry.path().extension() == ".grdecl") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    for (const fs::path& file : files) {
        if (!is_grid_file(file)) continue;
        GridCase c{file, {file}, {}};
        const std::string stem = file.stem().string();
        if (stem.size() > 4 && stem.compare(stem.size() - 4, 4, "grid") == 0) {
            const std::string prefix = stem.substr(0, stem.size() - 4);
            for (const fs::path& other : files)
                if (other != file && other.parent_path() == file.parent_path() &&
                    other.stem().string().rfind(prefix, 0) == 0 && !is_grid_file(other))
                    c.our_files.push_back(other);
        }
        for (char ch : fs::relative(file, kGrdeclDir).replace_extension().string())
            c.name += std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
        cases.push_back(std::move(c));
    }
    return cases;
}

// ---------------------------------------------------------------------------------------------
// OPM side.

/// One ZCORN value OPM's fixupZCORN changed.
struct ZcornRepair {
    std::size_t cell = 0;  ///< global index
    int corner = 0;        ///< OPM / our corner numbering (bit 0: i+1, bit 1: j+1, bit 2: bottom)
    int rule = 0;          ///< 1: cell to cell (layer overlap), 2: in cell (crossed edge)
    double file_value = 0;
    double opm_value = 0;
};

/// Eclipse-order index of corner `c` of cell (i, j, k) (OPM's ZcornMapper::index).
std::size_t zcorn_index(const GridDims& d, int i, int j, int k, int c) {
    const std::size_t nx = std::size_t(d.nx), ny = std::size_t(d.ny);
    return std::size_t(2 * i + (c & 1)) + (std::size_t(2 * j + ((c >> 1) & 1))) * 2 * nx +
           std::size_t(2 * k + (c >> 2)) * 4 * nx * ny;
}

/// Replays OPM's ZcornMapper::fixupZCORN (opm-common EclipseGrid.cpp, quoted at the top) on the
/// file's depths, recording which rule changed which value.
std::pair<std::vector<double>, std::vector<ZcornRepair>> replay_fixup_zcorn(const CornerPointGrid& grid) {
    const GridDims& d = grid.dims();
    std::vector<double> z(d.zcorn_value_count());
    for (std::size_t n = 0; n < z.size(); ++n) z[n] = grid.zcorn().value(n);
    const double sign = z[zcorn_index(d, 0, 0, 0, 0)] <= z[zcorn_index(d, 0, 0, d.nz - 1, 4)] ? 1.0 : -1.0;
    std::map<std::pair<std::size_t, int>, ZcornRepair> repairs;
    auto record = [&](int i, int j, int k, int c, int rule, double from, double to) {
        auto [it, fresh] = repairs.try_emplace({d.cell_index(i, j, k), c});
        if (fresh) it->second = {d.cell_index(i, j, k), c, rule, from, to};
        it->second.opm_value = to;
    };
    for (int k = 0; k < d.nz; ++k)
        for (int j = 0; j < d.ny; ++j)
            for (int i = 0; i < d.nx; ++i)
                for (int c = 0; c < 4; ++c) {
                    if (k > 0) {
                        const std::size_t above = zcorn_index(d, i, j, k - 1, c + 4);
                        const std::size_t top = zcorn_index(d, i, j, k, c);
                        if ((z[top] - z[above]) * sign < 0) {
                            record(i, j, k, c, 1, z[top], z[above]);
                            z[top] = z[above];
                        }
                    }
                    const std::size_t top = zcorn_index(d, i, j, k, c);
                    const std::size_t bottom = zcorn_index(d, i, j, k, c + 4);
                    if ((z[bottom] - z[top]) * sign < 0) {
                        record(i, j, k, c + 4, 2, z[bottom], z[top]);
                        z[bottom] = z[top];
                    }
                }
    std::vector<ZcornRepair> list;
    for (const auto& [key, repair] : repairs) list.push_back(repair);
    return {std::move(z), std::move(list)};
}

/// What the probe found (ZcornMapper::fixupZCORN on each shared grid file, OPM 2022.10):
/// file name -> {global cell, corner, rule, file value, OPM value}. Files not listed: no change.
const std::map<std::string, std::vector<ZcornRepair>>& known_repairs() {
    static const std::map<std::string, std::vector<ZcornRepair>> table = {
        // "overlap ** at node 2": the top of cell (0,0,1) at its i+1,j corner (690) lies above
        // the bottom of cell (0,0,0) there (710); OPM moves the top down to 710.
        {"sixcells2_described_zoverlap.grdecl", {{2, 1, 1, 690.0, 710.0}}},
    };
    return table;
}

// ---------------------------------------------------------------------------------------------
// Helpers on our side.

double diagonal(const Box3& b) {
    const double dx = b.max.x - b.min.x, dy = b.max.y - b.min.y, dz = b.max.z - b.min.z;
    return std::sqrt(dx * dx + dy * dy + dz * dz);
}

double opm_formula_volume(const CellCorners& corners) {
    std::array<double, 8> x{}, y{}, z{};
    for (std::size_t c = 0; c < 8; ++c) {
        x[c] = corners[c].x;
        y[c] = corners[c].y;
        z[c] = corners[c].z;
    }
    return calculateCellVol(x, y, z);
}

std::string sci(double value) {
    std::ostringstream text;
    text << std::scientific << std::setprecision(3) << value;
    return text.str();
}

std::string ijk_text(const GridDims& d, std::size_t cell) {
    const CellIjk ijk = cell_ijk(d, cell);
    return "(" + std::to_string(ijk.i) + "," + std::to_string(ijk.j) + "," + std::to_string(ijk.k) + ") #" +
           std::to_string(cell);
}

// ---------------------------------------------------------------------------------------------
// The per-file comparison.

class OpmReference : public ::testing::TestWithParam<GridCase> {};

TEST_P(OpmReference, MatchesEclipseGrid) {
    const GridCase& gc = GetParam();
    const std::string file_name = gc.grid_file.filename().string();
    SCOPED_TRACE(gc.grid_file.string());

    CornerPointGrid ours;
    ASSERT_NO_THROW(ours = load_grdecl(gc.our_files)) << "our reader rejected " << gc.grid_file;

    std::optional<Opm::EclipseGrid> opm;
    try {
        opm.emplace(opm_grid(gc.grid_file));
    } catch (const std::exception& e) {
        GTEST_SKIP() << "OPM cannot build an EclipseGrid from " << file_name << ": " << e.what();
    }

    // Dimensions, ACTNUM, active count.
    const GridDims& d = ours.dims();
    ASSERT_EQ(std::size_t(d.nx), opm->getNX());
    ASSERT_EQ(std::size_t(d.ny), opm->getNY());
    ASSERT_EQ(std::size_t(d.nz), opm->getNZ());
    ASSERT_EQ(ours.active_count(), opm->getNumActive());
    for (std::size_t g = 0; g < ours.cell_count(); ++g)
        ASSERT_EQ(ours.active(g), opm->cellActive(g)) << "ACTNUM differs at " << ijk_text(d, g);

    // COORD is used as read by both (METRES, no GRIDUNIT scaling in the shared files).
    const std::vector<double>& opm_coord = opm->getCOORD();
    ASSERT_EQ(opm_coord.size(), ours.coord().size());
    for (std::size_t n = 0; n < opm_coord.size(); ++n) ASSERT_EQ(opm_coord[n], ours.coord()[n]) << "COORD[" << n << "]";

    // ZCORN: OPM's array is exactly the file's array after fixupZCORN, as replayed here.
    const auto [replayed, repairs] = replay_fixup_zcorn(ours);
    const std::vector<double>& opm_zcorn = opm->getZCORN();
    ASSERT_EQ(opm_zcorn.size(), replayed.size());
    for (std::size_t n = 0; n < opm_zcorn.size(); ++n)
        ASSERT_EQ(opm_zcorn[n], replayed[n]) << "OPM's ZCORN[" << n << "] is not the replayed fixupZCORN value";
    std::size_t changed_values = 0;
    for (std::size_t n = 0; n < opm_zcorn.size(); ++n) changed_values += opm_zcorn[n] != ours.zcorn().value(n);
    EXPECT_EQ(changed_values, repairs.size());
    EXPECT_EQ(opm->getZcornFixed(), repairs.size());  // each value is adjusted at most once

    // The repairs are the ones the probe documented (files not in the table: none).
    {
        const auto it = known_repairs().find(file_name);
        const std::vector<ZcornRepair> expected = it == known_repairs().end() ? std::vector<ZcornRepair>{} : it->second;
        ASSERT_EQ(repairs.size(), expected.size()) << "OPM repaired a different number of ZCORN values than documented";
        for (std::size_t n = 0; n < expected.size(); ++n) {
            EXPECT_EQ(repairs[n].cell, expected[n].cell);
            EXPECT_EQ(repairs[n].corner, expected[n].corner);
            EXPECT_EQ(repairs[n].rule, expected[n].rule);
            EXPECT_EQ(repairs[n].file_value, expected[n].file_value);
            EXPECT_EQ(repairs[n].opm_value, expected[n].opm_value);
        }
    }

    std::set<std::size_t> repaired_cells, repaired_in_cell;  // rule 1 or 2; rule 2 only
    for (const ZcornRepair& r : repairs) {
        repaired_cells.insert(r.cell);
        if (r.rule == 2) repaired_in_cell.insert(r.cell);
    }

    // What we flag. classify_shape sees the file's ZCORN, cell by cell: a crossed pillar edge
    // (bottom above top) is `inverted`; a layer overlapping the one above is not its business.
    // Both decide the depth direction the same way, so a crossed edge in the file is always
    // repaired by OPM's rule 2: our inverted cells == cells OPM repaired with rule 2, and the
    // cells repaired by rule 1 only are not flagged inverted by us.
    std::set<std::size_t> inverted;
    for (int k = 0; k < d.nz; ++k)
        for (int j = 0; j < d.ny; ++j)
            for (int i = 0; i < d.nx; ++i)
                if (classify_shape(ours, i, j, k, 0.0) == CellShape::inverted) inverted.insert(d.cell_index(i, j, k));
    {
        std::set<std::size_t> rule2_from_file;  // rule 2 cells whose edge was crossed in the file
        for (const ZcornRepair& r : repairs)
            if (r.rule == 2) {
                const int c = r.corner & 3;
                const CellIjk ijk = cell_ijk(d, r.cell);
                const double thickness = ours.zcorn().corner_depth(ijk.i, ijk.j, ijk.k, c | 4) -
                                         ours.zcorn().corner_depth(ijk.i, ijk.j, ijk.k, c);
                if (ours.depth_direction() * thickness < 0) rule2_from_file.insert(r.cell);
            }
        EXPECT_EQ(inverted, rule2_from_file) << "cells we flag inverted vs cells OPM collapsed (crossed in the file)";
        for (std::size_t cell : inverted) EXPECT_TRUE(repaired_in_cell.count(cell)) << ijk_text(d, cell);
    }
    for (std::size_t cell : repaired_cells) {
        if (repaired_in_cell.count(cell)) continue;
        const CellIjk ijk = cell_ijk(d, cell);
        EXPECT_NE(classify_shape(ours, ijk.i, ijk.j, ijk.k, 0.0), CellShape::inverted)
            << "overlap-only repair at " << ijk_text(d, cell);
    }
    // Rule 1 on values as written (not on values an earlier repair moved): exactly the cells we
    // flag as overlapping the layer above.
    std::set<std::size_t> overlapping, rule1_from_file;
    for (int k = 0; k < d.nz; ++k)
        for (int j = 0; j < d.ny; ++j)
            for (int i = 0; i < d.nx; ++i)
                if (overlaps_layer_above(ours, i, j, k, 0.0)) overlapping.insert(d.cell_index(i, j, k));
    for (const ZcornRepair& r : repairs) {
        const CellIjk ijk = cell_ijk(d, r.cell);
        const int c = r.corner & 3;
        if (r.rule == 1 && ours.depth_direction() * (ours.zcorn().corner_depth(ijk.i, ijk.j, ijk.k, c) -
                                                     ours.zcorn().corner_depth(ijk.i, ijk.j, ijk.k - 1, c | 4)) < 0)
            rule1_from_file.insert(r.cell);
    }
    EXPECT_EQ(overlapping, rule1_from_file) << "cells we flag overlapping vs cells OPM cut (overlap in the file)";

    // Geometry of every active cell OPM did not repair: corners, volume, centre.
    const double diag = diagonal(grid_bounds(ours));
    ASSERT_GT(diag, 0.0);
    const double centre_tol = kCentreRelTol * diag;
    std::size_t compared = 0;
    double worst_volume = 0, worst_centre = 0;  // relative differences, reported as test properties
    for (std::size_t g = 0; g < ours.cell_count(); ++g) {
        if (!ours.active(g) || repaired_cells.count(g)) continue;
        const CellIjk ijk = cell_ijk(d, g);
        const CellCorners corners = cell_corners(ours, ijk.i, ijk.j, ijk.k);
        for (int c = 0; c < 8; ++c) {
            const auto p = opm->getCornerPos(std::size_t(ijk.i), std::size_t(ijk.j), std::size_t(ijk.k), std::size_t(c));
            const Point3& q = corners[std::size_t(c)];
            ASSERT_NEAR(q.x, p[0], centre_tol) << "corner " << c << " of " << ijk_text(d, g);
            ASSERT_NEAR(q.y, p[1], centre_tol) << "corner " << c << " of " << ijk_text(d, g);
            ASSERT_EQ(q.z, p[2]) << "corner " << c << " of " << ijk_text(d, g);
        }
        const double opm_volume = opm->getCellVolume(g);
        const double our_volume = cell_volume(corners);
        ASSERT_GE(opm_volume, 0.0);
        ASSERT_NEAR(our_volume, opm_volume, kVolumeRelTol * opm_volume) << "volume of " << ijk_text(d, g);
        const auto oc = opm->getCellCenter(g);
        const Point3 centre = cell_centre(corners);
        ASSERT_NEAR(centre.x, oc[0], centre_tol) << "centre of " << ijk_text(d, g);
        ASSERT_NEAR(centre.y, oc[1], centre_tol) << "centre of " << ijk_text(d, g);
        ASSERT_NEAR(centre.z, oc[2], centre_tol) << "centre of " << ijk_text(d, g);
        if (opm_volume > 0) worst_volume = std::max(worst_volume, std::abs(our_volume - opm_volume) / opm_volume);
        worst_centre = std::max({worst_centre, std::abs(centre.x - oc[0]) / diag, std::abs(centre.y - oc[1]) / diag,
                                 std::abs(centre.z - oc[2]) / diag});
        ++compared;
    }
    RecordProperty("compared_active_cells", std::to_string(compared));
    RecordProperty("opm_repaired_cells", std::to_string(repaired_cells.size()));
    RecordProperty("max_volume_rel_diff", sci(worst_volume));
    RecordProperty("max_centre_diff_over_diagonal", sci(worst_centre));
    EXPECT_EQ(compared + [&] {
        std::size_t n = 0;
        for (std::size_t cell : repaired_cells) n += ours.active(cell);
        return n;
    }(), ours.active_count());

    // Repaired cells, separately. (a) From the file's ZCORN (ours) OPM's own volume formula
    // gives our volume: the formulas agree. (b) Our geometry on OPM's repaired ZCORN gives OPM's
    // volume and centre: the repair is the whole difference. (c) Record how far apart they are.
    if (!repaired_cells.empty()) {
        const CornerPointGrid on_opm_zcorn(d, ours.coord(), ZcornStore::from_values(d, opm_zcorn), ours.actnum());
        for (std::size_t g : repaired_cells) {
            const CellIjk ijk = cell_ijk(d, g);
            const CellCorners as_written = cell_corners(ours, ijk.i, ijk.j, ijk.k);
            const CellCorners as_repaired = cell_corners(on_opm_zcorn, ijk.i, ijk.j, ijk.k);
            const double our_volume = cell_volume(as_written);
            const double formula_volume = opm_formula_volume(as_written);
            EXPECT_NEAR(our_volume, formula_volume, kVolumeRelTol * formula_volume) << ijk_text(d, g);
            const double opm_volume = opm->getCellVolume(g);
            EXPECT_NEAR(cell_volume(as_repaired), opm_volume, kVolumeRelTol * opm_volume) << ijk_text(d, g);
            const auto oc = opm->getCellCenter(g);
            const Point3 centre = cell_centre(as_repaired);
            EXPECT_NEAR(centre.x, oc[0], centre_tol) << ijk_text(d, g);
            EXPECT_NEAR(centre.y, oc[1], centre_tol) << ijk_text(d, g);
            EXPECT_NEAR(centre.z, oc[2], centre_tol) << ijk_text(d, g);
            const Point3 written_centre = cell_centre(as_written);
            RecordProperty("repaired_cell_" + std::to_string(g),
                           "ours (file ZCORN) volume " + std::to_string(our_volume) + " centre z " +
                               std::to_string(written_centre.z) + "; OPM (repaired) volume " +
                               std::to_string(opm_volume) + " centre z " + std::to_string(oc[2]));
        }
    }
}

INSTANTIATE_TEST_SUITE_P(SharedGrdecl, OpmReference, ::testing::ValuesIn(discover_cases()),
                         [](const ::testing::TestParamInfo<GridCase>& info) { return info.param.name; });

TEST(OpmReferenceData, SharedFilesPresent) {
    const std::vector<GridCase> cases = discover_cases();
    ASSERT_FALSE(cases.empty()) << "no *.grdecl grid under " << kGrdeclDir;
    const auto reek = std::find_if(cases.begin(), cases.end(),
                                   [](const GridCase& c) { return c.grid_file.filename() == "reek_sim_grid.grdecl"; });
    ASSERT_NE(reek, cases.end());
    ASSERT_EQ(reek->our_files.size(), 2u);
    EXPECT_EQ(reek->our_files[1].filename(), "reek_sim_poro.grdecl");
}

// ---------------------------------------------------------------------------------------------
// DATA.md's documented Reek numbers, for both readers.

TEST(OpmReferenceData, ReekDocumentedNumbers) {
    const fs::path grid_file = kGrdeclDir / "reek" / "reek_sim_grid.grdecl";
    const fs::path poro_file = kGrdeclDir / "reek" / "reek_sim_poro.grdecl";
    const CornerPointGrid ours = load_grdecl({grid_file, poro_file});
    ASSERT_EQ(ours.dims(), (GridDims{40, 64, 14}));
    EXPECT_EQ(ours.cell_count(), 35840u);
    EXPECT_EQ(ours.active_count(), 35838u);
    EXPECT_NE(ours.property("PORO"), nullptr);

    const CellCorners corners = cell_corners(ours, 0, 0, 0);
    ASSERT_TRUE(ours.active(0));
    EXPECT_NEAR(cell_volume(corners), 108688.95, 0.005);
    const Point3 centre = cell_centre(corners);
    EXPECT_NEAR(centre.x, 110.166, 0.0005);
    EXPECT_NEAR(centre.y, 8779.689, 0.0005);
    EXPECT_NEAR(centre.z, 1727.649, 0.0005);

    Opm::EclipseGrid opm = opm_grid(grid_file);  // not const: getZcornFixed() is not const
    EXPECT_EQ(opm.getNumActive(), 35838u);
    EXPECT_EQ(opm.getZcornFixed(), 0u);
    EXPECT_NEAR(opm.getCellVolume(0), 108688.95, 0.005);
    const auto oc = opm.getCellCenter(0);
    EXPECT_NEAR(oc[0], 110.166, 0.0005);
    EXPECT_NEAR(oc[1], 8779.689, 0.0005);
    EXPECT_NEAR(oc[2], 1727.649, 0.0005);
}

// OPM 2022.10 pitfall behind the GRID-section wrapper: a bare GRDECL deck loses its ACTNUM.
TEST(OpmSemantics, BareGrdeclDeckIgnoresActnum) {
    const fs::path file = kGrdeclDir / "small" / "dual_distorted1.grdecl";  // 15 cells, 2 inactive
    const CornerPointGrid ours = load_grdecl({file});
    ASSERT_EQ(ours.active_count(), 13u);

    Opm::Parser parser;
    const Opm::ParseContext context = lenient_parse_context();
    Opm::ErrorGuard errors;
    const Opm::Deck bare = parser.parseFile(file.string(), context, errors);
    errors.clear();
    EXPECT_EQ(Opm::EclipseGrid(bare).getNumActive(), 15u) << "OPM now applies a bare deck's ACTNUM; "
                                                              "the GRID wrapper may no longer be needed";
    const std::vector<int> actnum = bare["ACTNUM"].back().getIntData();
    EXPECT_EQ(Opm::EclipseGrid(bare, actnum.data()).getNumActive(), 13u);
    EXPECT_EQ(opm_grid(file).getNumActive(), 13u);
}

// ---------------------------------------------------------------------------------------------
// Pillar and volume semantics on hand-made grids (EclipseGrid from arrays; no fixup triggers).

/// 1x1x1 grid from 4 pillars and 8 depths, both ways.
struct TinyPair {
    CornerPointGrid ours;
    Opm::EclipseGrid opm;
};

TinyPair tiny_pair(const std::vector<double>& coord, const std::vector<double>& zcorn) {
    const GridDims d{1, 1, 1};
    return {CornerPointGrid(d, coord, ZcornStore::from_values(d, zcorn), {}),
            Opm::EclipseGrid(std::array<int, 3>{1, 1, 1}, coord, zcorn)};
}

TEST(OpmSemantics, PillarPointMatches) {
    // Pillars: tilted (x and y change with depth), vertical, a pillar whose top and bottom share
    // a depth (zt == zb) but not x/y, and a pillar given bottom-up (zt > zb).
    const std::vector<double> coord = {
        0.0,  0.0,  1000.0, 10.0, -5.0, 2000.0,  // tilted
        100.0, 0.0, 1000.0, 100.0, 0.0, 2000.0,  // vertical
        0.0, 100.0, 1500.0, 30.0, 130.0, 1500.0,  // zt == zb: OPM and we use the top point
        100.0, 100.0, 2000.0, 90.0, 95.0, 1000.0,  // upside down
    };
    const std::vector<double> zcorn = {1100, 1200, 1300, 1400, 1600, 1700, 1800, 1900};
    const TinyPair t = tiny_pair(coord, zcorn);
    const CellCorners corners = cell_corners(t.ours, 0, 0, 0);
    for (int c = 0; c < 8; ++c) {
        const auto p = t.opm.getCornerPos(0, 0, 0, std::size_t(c));
        EXPECT_NEAR(corners[std::size_t(c)].x, p[0], 1e-9) << "corner " << c;
        EXPECT_NEAR(corners[std::size_t(c)].y, p[1], 1e-9) << "corner " << c;
        EXPECT_EQ(corners[std::size_t(c)].z, p[2]) << "corner " << c;
    }
    // zt == zb: x, y of the top point at every depth.
    EXPECT_EQ(corners[2].x, 0.0);
    EXPECT_EQ(corners[2].y, 100.0);
    EXPECT_EQ(corners[6].x, 0.0);
    EXPECT_EQ(corners[6].y, 100.0);
    // OPM: x = xt + (xb - xt) / (zt - zb) * (zt - Z) for the tilted pillar at Z = 1100.
    EXPECT_NEAR(corners[0].x, 0.0 + (10.0 - 0.0) / (1000.0 - 2000.0) * (1000.0 - 1100.0), 1e-12);
}

TEST(OpmSemantics, VolumeIsAbsolute) {
    // Unit-ish box and its mirror image (i running towards -x): left-handed, signed volume < 0.
    const std::vector<double> right = {0, 0, 0, 0, 0, 1, 2, 0, 0, 2, 0, 1, 0, 3, 0, 0, 3, 1, 2, 3, 0, 2, 3, 1};
    const std::vector<double> left = {2, 0, 0, 2, 0, 1, 0, 0, 0, 0, 0, 1, 2, 3, 0, 2, 3, 1, 0, 3, 0, 0, 3, 1};
    const std::vector<double> zcorn = {0, 0, 0, 0, 0.5, 0.5, 0.5, 0.5};
    for (const auto* coord : {&right, &left}) {
        const TinyPair t = tiny_pair(*coord, zcorn);
        const CellCorners corners = cell_corners(t.ours, 0, 0, 0);
        EXPECT_NEAR(t.opm.getCellVolume(0), 3.0, 1e-12);
        EXPECT_NEAR(cell_volume(corners), 3.0, 1e-12);
        EXPECT_NEAR(std::abs(signed_volume(corners)), 3.0, 1e-12);
    }
    EXPECT_GT(signed_volume(cell_corners(tiny_pair(right, zcorn).ours, 0, 0, 0)), 0.0);
    EXPECT_LT(signed_volume(cell_corners(tiny_pair(left, zcorn).ours, 0, 0, 0)), 0.0);

    // calculateCellVol is |integral of the Jacobian|, not the integral of |Jacobian|: one crossed
    // pillar edge (as OPM would see it before fixupZCORN) gives the same number as our |signed|.
    std::array<double, 8> x{0, 1, 0, 1, 0, 1, 0, 1}, y{0, 0, 1, 1, 0, 0, 1, 1}, z{0, 0, 0, 0, 1, 1, 1, -1};
    CellCorners crossed;
    for (std::size_t c = 0; c < 8; ++c) crossed[c] = {x[c], y[c], z[c]};
    EXPECT_NEAR(calculateCellVol(x, y, z), 0.5, 1e-12);
    EXPECT_NEAR(cell_volume(crossed), 0.5, 1e-12);
    std::array<double, 8> zi{1, 1, 1, 1, 0, 0, 0, 0};  // fully inverted cell
    EXPECT_NEAR(calculateCellVol(x, y, zi), 1.0, 1e-12);
}

// fixupZCORN's rule 2 (no shared file exercises it): a crossed pillar edge is collapsed, and the
// collapse then propagates to the layer below through rule 1. We flag the crossed cell inverted.
TEST(OpmSemantics, FixupZcornCollapsesCrossedEdge) {
    const GridDims d{1, 1, 2};
    const std::vector<double> coord = {0, 0, 0, 0, 0, 10, 1, 0, 0, 1, 0, 10, 0, 1, 0, 0, 1, 10, 1, 1, 0, 1, 1, 10};
    const std::vector<double> zcorn = {
        0, 0, 0, 0,          // layer 0 top
        1, 1, 1, -0.5,       // layer 0 bottom: corner 3 (i+1, j+1) above its top -> crossed
        1, 1, 1, -0.5,       // layer 1 top, equal to the bottom above as written
        2, 2, 2, 2,          // layer 1 bottom
    };
    const CornerPointGrid ours(d, coord, ZcornStore::from_values(d, zcorn), {});
    Opm::EclipseGrid opm(std::array<int, 3>{1, 1, 2}, coord, zcorn);

    const auto [replayed, repairs] = replay_fixup_zcorn(ours);
    EXPECT_EQ(opm.getZCORN(), replayed);
    ASSERT_EQ(repairs.size(), 2u);
    EXPECT_EQ(repairs[0].cell, 0u);  // rule 2: bottom of layer 0 at corner 3 -> 0
    EXPECT_EQ(repairs[0].corner, 7);
    EXPECT_EQ(repairs[0].rule, 2);
    EXPECT_EQ(repairs[0].opm_value, 0.0);
    EXPECT_EQ(repairs[1].cell, 1u);  // rule 1: top of layer 1 at corner 3 follows it -> 0
    EXPECT_EQ(repairs[1].corner, 3);
    EXPECT_EQ(repairs[1].rule, 1);
    EXPECT_EQ(repairs[1].opm_value, 0.0);
    EXPECT_EQ(opm.getZcornFixed(), 2u);

    EXPECT_EQ(classify_shape(ours, 0, 0, 0, 0.0), CellShape::inverted);
    EXPECT_EQ(classify_shape(ours, 0, 0, 1, 0.0), CellShape::regular);

    // As written, OPM's formula and ours agree; OPM reports the repaired cell's volume.
    const CellCorners written = cell_corners(ours, 0, 0, 0);
    EXPECT_NEAR(cell_volume(written), opm_formula_volume(written), 1e-12);
    const CornerPointGrid repaired(d, coord, ZcornStore::from_values(d, opm.getZCORN()), {});
    for (int k = 0; k < 2; ++k) {
        const std::size_t g = d.cell_index(0, 0, k);
        EXPECT_NEAR(cell_volume(cell_corners(repaired, 0, 0, k)), opm.getCellVolume(g), 1e-12) << "layer " << k;
    }
    EXPECT_GT(std::abs(cell_volume(written) - opm.getCellVolume(0)), 0.01);
}

// A grid whose depths decrease with k (z up, or depths given as elevations): OPM's fixupZCORN
// takes its direction from ZCORN (sign = -1) and leaves the grid alone; our depth_direction() is
// decided the same way, so nothing is flagged. Volumes agree (both are absolute).
TEST(OpmSemantics, DepthDecreasingWithK) {
    const GridDims d{1, 1, 1};
    const std::vector<double> coord = {0, 0, 10, 0, 0, 0, 1, 0, 10, 1, 0, 0, 0, 1, 10, 0, 1, 0, 1, 1, 10, 1, 1, 0};
    const std::vector<double> zcorn = {10, 10, 10, 10, 0, 0, 0, 0};
    const CornerPointGrid ours(d, coord, ZcornStore::from_values(d, zcorn), {});
    Opm::EclipseGrid opm(std::array<int, 3>{1, 1, 1}, coord, zcorn);
    EXPECT_EQ(opm.getZcornFixed(), 0u);
    EXPECT_EQ(opm.getZCORN(), zcorn);
    EXPECT_EQ(ours.depth_direction(), -1);
    EXPECT_EQ(classify_shape(ours, 0, 0, 0, 0.0), CellShape::regular);
    EXPECT_NEAR(cell_volume(cell_corners(ours, 0, 0, 0)), opm.getCellVolume(0), 1e-12);
    EXPECT_NEAR(opm.getCellVolume(0), 10.0, 1e-12);
}

}  // namespace

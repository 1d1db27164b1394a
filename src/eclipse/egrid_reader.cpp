#include "eclipse/egrid_reader.h"

#include <algorithm>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include <opm/io/eclipse/EGrid.hpp>
#include <opm/io/eclipse/EclFile.hpp>

#include "eclipse/eclio_access.h"

namespace cutaway::eclipse {
namespace {

namespace fs = std::filesystem;
using Opm::EclIO::EGrid;

const std::string egrid_expected = "an Eclipse binary grid (EGRID with GRIDHEAD, COORD, ZCORN)";

std::unique_ptr<EGrid> open_egrid(const fs::path& egrid) {
    if (!fs::is_regular_file(egrid)) throw EclipseError({egrid.string(), "", "an EGRID file", "no such file"});
    // The array list first: EGrid's constructor reads GRIDHEAD's dimensions without checking that
    // the file has one (another file type reached a vector resize of an uninitialised size).
    const auto listing = read_checked(egrid, "", egrid_expected,
                                      [&] { return std::make_unique<Opm::EclIO::EclFile>(egrid.string()); });
    if (!listing->hasKey("GRIDHEAD")) {
        const std::vector<Opm::EclIO::EclFile::EclEntry> arrays = listing->getList();
        throw EclipseError({egrid.string(), "", egrid_expected,
                            "no GRIDHEAD (first array " + (arrays.empty() ? std::string("none") : std::get<0>(arrays.front())) + ")"});
    }
    auto file = read_checked(egrid, "", egrid_expected, [&] { return std::make_unique<EGrid>(egrid.string()); });
    if (file->is_radial()) throw EclipseError({egrid.string(), "GRIDHEAD", "a corner-point grid", "a radial grid"});
    return file;
}

grid::GridDims dims_of(const EGrid& file, const fs::path& egrid) {
    const std::array<int, 3>& n = file.dimension();
    if (n[0] <= 0 || n[1] <= 0 || n[2] <= 0)
        throw EclipseError({egrid.string(), "GRIDHEAD", "positive NX NY NZ",
                            std::to_string(n[0]) + " " + std::to_string(n[1]) + " " + std::to_string(n[2])});
    return {n[0], n[1], n[2]};
}

/// Index of the first array called `name` (the global grid's: local grids follow it), or -1.
int first_index(const EGrid& file, const std::string& name) {
    const std::vector<std::string>& names = file.arrayNames();
    const auto found = std::find(names.begin(), names.end(), name);
    return found == names.end() ? -1 : int(found - names.begin());
}

/// The global grid's array `name` (required), checked to hold `count` values; EclIO's copy (held
/// by `file`), not another.
template <typename T>
const std::vector<T>& read_array(EGrid& file, const fs::path& egrid, const std::string& name, std::size_t count) {
    const int index = first_index(file, name);
    if (index < 0) throw EclipseError({egrid.string(), name, "the array in the file", "none"});
    const std::vector<T>& values = read_checked(egrid, name, std::to_string(count) + " values",
                                                [&]() -> const std::vector<T>& { return file.get<T>(index); });
    if (values.size() != count)
        throw EclipseError({egrid.string(), name, std::to_string(count) + " values", std::to_string(values.size())});
    return values;
}

/// The first item of the CHAR array `name`, trimmed; empty when the file has none.
std::string first_word(EGrid& file, const fs::path& egrid, const std::string& name) {
    const int index = first_index(file, name);
    if (index < 0) return {};
    const auto& words = read_checked(egrid, name, "text",
                                     [&]() -> const std::vector<std::string>& { return file.get<std::string>(index); });
    if (words.empty()) return {};
    std::string word = words.front();
    word.erase(word.find_last_not_of(' ') + 1);
    return word;
}

}  // namespace

grid::GridDims read_egrid_dims(const fs::path& egrid) {
    const std::unique_ptr<EGrid> file = open_egrid(egrid);
    return dims_of(*file, egrid);
}

grid::CornerPointGrid read_egrid(const fs::path& egrid, std::size_t memory_limit_bytes) {
    const std::unique_ptr<EGrid> file = open_egrid(egrid);
    const grid::GridDims dims = dims_of(*file, egrid);
    // EclIO's float copies and ours (double COORD, ZCORN possibly in its full layout, byte ACTNUM)
    // are held together while the grid is built.
    const std::size_t needed = sizeof(float) * (dims.coord_value_count() + dims.zcorn_value_count()) +
                               sizeof(int) * dims.cell_count() + sizeof(double) * dims.coord_value_count() +
                               grid::ZcornStore::full_bytes(dims) + dims.cell_count();
    require_within_memory(egrid, "COORD, ZCORN and ACTNUM", needed, memory_limit_bytes);

    const std::vector<float>& coord_values = read_array<float>(*file, egrid, "COORD", dims.coord_value_count());
    std::vector<double> coord(coord_values.begin(), coord_values.end());
    grid::ZcornStore zcorn(dims);
    for (float depth : read_array<float>(*file, egrid, "ZCORN", dims.zcorn_value_count())) zcorn.push(depth);
    std::vector<std::uint8_t> actnum(dims.cell_count(), 1);
    if (first_index(*file, "ACTNUM") >= 0) {
        const std::vector<int>& flags = read_array<int>(*file, egrid, "ACTNUM", dims.cell_count());
        std::transform(flags.begin(), flags.end(), actnum.begin(), [](int flag) { return std::uint8_t(flag != 0); });
    }
    grid::CornerPointGrid result(dims, std::move(coord), std::move(zcorn), std::move(actnum));

    grid::GridMetadata& meta = result.metadata();
    const std::vector<float>& mapaxes = file->get_mapaxes();
    if (mapaxes.size() == 6) {
        std::array<double, 6> axes{};
        std::copy(mapaxes.begin(), mapaxes.end(), axes.begin());
        meta.mapaxes = axes;
    }
    meta.map_units = file->get_mapunits();
    meta.map_units.erase(meta.map_units.find_last_not_of(' ') + 1);
    meta.grid_unit = first_word(*file, egrid, "GRIDUNIT");
    return result;
}

}  // namespace cutaway::eclipse

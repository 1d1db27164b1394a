#include "eclipse/init_reader.h"

#include <algorithm>
#include <array>
#include <memory>
#include <tuple>

#include <opm/io/eclipse/EInit.hpp>
#include <opm/output/eclipse/VectorItems/intehead.hpp>

#include "eclipse/eclio_access.h"

namespace cutaway::eclipse {
namespace {

namespace fs = std::filesystem;
using Opm::EclIO::EInit;
using Opm::EclIO::eclArrType;
using Head = Opm::RestartIO::Helpers::VectorItems::intehead;

/// Header and table arrays whose length may equal a small grid's cell count by chance.
const std::array<std::string, 5> non_cell_arrays = {"INTEHEAD", "LOGIHEAD", "DOUBHEAD", "TABDIMS", "TAB"};

struct CellArray {
    std::string name;
    eclArrType type;
    std::size_t size;  ///< values in the file: the active count or the cell count
};

std::unique_ptr<EInit> open_init(const fs::path& init, const grid::CornerPointGrid& grid) {
    if (!fs::is_regular_file(init)) throw EclipseError({init.string(), "", "an INIT file", "no such file"});
    auto file = read_checked(init, "", "an Eclipse binary INIT file (INTEHEAD, cell arrays)",
                             [&] { return std::make_unique<EInit>(init.string()); });
    const std::array<int, 3> n = file->grid_dimension();
    const grid::GridDims& d = grid.dims();
    const int active = file->activeCells();
    if (n[0] != d.nx || n[1] != d.ny || n[2] != d.nz || std::size_t(active) != grid.active_count())
        throw EclipseError({init.string(), "INTEHEAD",
                            "the EGRID's grid: " + std::to_string(d.nx) + " x " + std::to_string(d.ny) + " x " +
                                std::to_string(d.nz) + " cells, " + std::to_string(grid.active_count()) + " active",
                            std::to_string(n[0]) + " x " + std::to_string(n[1]) + " x " + std::to_string(n[2]) +
                                " cells, " + std::to_string(active) + " active"});
    return file;
}

std::vector<CellArray> cell_arrays(const EInit& file, const grid::CornerPointGrid& grid) {
    std::vector<CellArray> arrays;
    for (const auto& [name, type, size] : file.list_arrays()) {
        const bool numeric = type == eclArrType::REAL || type == eclArrType::DOUB || type == eclArrType::INTE;
        const bool cell_sized = std::size_t(size) == grid.active_count() || std::size_t(size) == grid.cell_count();
        const bool header = std::find(non_cell_arrays.begin(), non_cell_arrays.end(), name) != non_cell_arrays.end();
        if (numeric && cell_sized && !header) arrays.push_back({name, type, std::size_t(size)});
    }
    return arrays;
}

/// One value per cell of `values` (one per active cell or already one per cell).
template <typename Out, typename In>
std::vector<Out> per_cell(const std::vector<In>& values, const grid::CornerPointGrid& grid) {
    if (values.size() == grid.cell_count()) return std::vector<Out>(values.begin(), values.end());
    return spread_over_cells<Out>(values, grid.actnum());
}

template <typename T>
const std::vector<T>& init_data(EInit& file, const fs::path& init, const CellArray& array) {
    const std::vector<T>& values =
        read_checked(init, array.name, std::to_string(array.size) + " values",
                     [&]() -> const std::vector<T>& { return file.getInitData<T>(array.name); });
    if (values.size() != array.size)
        throw EclipseError({init.string(), array.name, std::to_string(array.size) + " values", std::to_string(values.size())});
    return values;
}

}  // namespace

void add_init_properties(grid::CornerPointGrid& grid, const fs::path& init, std::size_t memory_limit_bytes,
                         const std::optional<std::string>& only) {
    const std::unique_ptr<EInit> file = open_init(init, grid);
    const auto& head = read_checked(init, "INTEHEAD", "a readable header",
                                    [&]() -> const std::vector<int>& { return file->getInitData<int>("INTEHEAD"); });
    if (head.size() > std::size_t(Head::UNIT)) grid.metadata().unit_system = unit_system_name(head[Head::UNIT]);
    std::vector<CellArray> arrays = cell_arrays(*file, grid);
    if (only) std::erase_if(arrays, [&](const CellArray& array) { return array.name != *only; });
    // EclIO keeps every array it read until the file closes, beside our one-per-cell copies.
    std::size_t needed = 0;
    for (const CellArray& array : arrays)
        needed += array.size * (array.type == eclArrType::DOUB ? sizeof(double) : sizeof(float)) +
                  grid.cell_count() * sizeof(float);
    require_within_memory(init, only ? *only : "every cell array", needed, memory_limit_bytes);
    for (const CellArray& array : arrays) {
        if (array.type == eclArrType::INTE)
            grid.set_int_property(array.name, per_cell<std::int32_t>(init_data<int>(*file, init, array), grid));
        else if (array.type == eclArrType::DOUB)
            grid.set_property(array.name, per_cell<float>(init_data<double>(*file, init, array), grid));
        else
            grid.set_property(array.name, per_cell<float>(init_data<float>(*file, init, array), grid));
    }
}

}  // namespace cutaway::eclipse

#include "wells/well.h"

#include "io/bad_input_error.h"

namespace cutaway::wells {

const char* to_string(WellKind kind) {
    switch (kind) {
    case WellKind::producer: return "producer";
    case WellKind::injector: return "injector";
    case WellKind::unknown: return "unknown";
    }
    return "unknown";
}

const char* to_string(WellStatus status) {
    switch (status) {
    case WellStatus::open: return "open";
    case WellStatus::stop: return "stop";
    case WellStatus::shut: return "shut";
    case WellStatus::automatic: return "auto";
    }
    return "open";
}

std::array<float, 3> well_colour(const Well& well) {
    if (well.status == WellStatus::shut || well.status == WellStatus::stop) return {0.55f, 0.55f, 0.55f};
    switch (well.kind) {
    case WellKind::injector: return {0.10f, 0.35f, 1.00f};
    case WellKind::producer: return {1.00f, 0.32f, 0.05f};
    case WellKind::unknown: return {0.90f, 0.15f, 0.80f};
    }
    return {0.90f, 0.15f, 0.80f};
}

namespace {
std::string cell_text(int i, int j, int k) {
    // 1-based, as the deck and the simulator's reports write cells.
    std::string text = "(";
    text += std::to_string(i + 1);
    text += ", " + std::to_string(j + 1);
    text += ", " + std::to_string(k + 1);
    return text + ")";
}
}  // namespace

void check_within_grid(const std::vector<Well>& wells, const grid::GridDims& d, const std::string& source) {
    const std::string grid_text = "a cell of the model's " + std::to_string(d.nx) + " x " + std::to_string(d.ny) + " x " +
                                  std::to_string(d.nz) + " cells (1-based I, J, K)";
    for (const Well& well : wells) {
        if (!d.contains(well.head_i, well.head_j, 0))
            throw io::BadInputError(source + ": well " + well.name + ": wellhead column (I, J) expected within 1.." +
                                    std::to_string(d.nx) + ", 1.." + std::to_string(d.ny) + ", found (" +
                                    std::to_string(well.head_i + 1) + ", " + std::to_string(well.head_j + 1) + ")");
        for (const WellConnection& c : well.connections)
            if (!d.contains(c.i, c.j, c.k))
                throw io::BadInputError(source + ": well " + well.name + ": connection expected in " + grid_text +
                                        ", found " + cell_text(c.i, c.j, c.k));
    }
}

}  // namespace cutaway::wells

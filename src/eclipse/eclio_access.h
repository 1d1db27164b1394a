#pragma once
// What the EGRID, INIT and UNRST readers share: EclIO's exceptions turned into one EclipseError
// line, the memory check made before an array is read, and active-cell arrays spread over all cells.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <new>
#include <string>
#include <vector>

#include "eclipse/eclipse_error.h"

namespace cutaway::eclipse {

/// The first line of an EclIO message (OPM's exceptions may carry a trace on further lines),
/// without the "[source.cpp:line] " OPM_THROW puts before it.
std::string first_line(const std::string& message);

/// Runs `read` (calls into opm-common's EclIO on `file`) and rethrows whatever EclIO throws as an
/// EclipseError naming `file`, `array` and what was `expected`; std::bad_alloc passes through.
template <typename Read>
auto read_checked(const std::filesystem::path& file, const std::string& array, const std::string& expected, Read&& read)
    -> decltype(read()) {
    try {
        return read();
    } catch (const EclipseError&) {
        throw;
    } catch (const std::bad_alloc&) {
        throw;
    } catch (const std::exception& error) {
        throw EclipseError({file.string(), array, expected, first_line(error.what())});
    }
}

/// Throws EclipseError naming `file` and `what` is read (e.g. "COORD, ZCORN and ACTNUM") when
/// reading needs more than `limit_bytes` (the --memory-limit-gb budget left for it), before
/// anything is allocated.
void require_within_memory(const std::filesystem::path& file, const std::string& what, std::size_t needed_bytes,
                           std::size_t limit_bytes);

/// Eclipse's name of INTEHEAD's unit convention item (1 METRIC, 2 FIELD, 3 LAB, 4 PVT-M); empty
/// for another code.
std::string unit_system_name(int code);

/// One value per cell from one per active cell (`actnum` order), inactive cells 0: simulators write
/// INIT and restart arrays for active cells only. `active_values.size()` must equal the active count.
template <typename Out, typename In>
std::vector<Out> spread_over_cells(const std::vector<In>& active_values, const std::vector<std::uint8_t>& actnum) {
    std::vector<Out> cells(actnum.size(), Out(0));
    std::size_t next = 0;
    for (std::size_t cell = 0; cell < actnum.size(); ++cell)
        if (actnum[cell]) cells[cell] = Out(active_values[next++]);
    return cells;
}

}  // namespace cutaway::eclipse

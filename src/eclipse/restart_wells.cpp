#include "eclipse/restart_wells.h"

#include <algorithm>
#include <string>

#include <opm/input/eclipse/Schedule/ScheduleTypes.hpp>
#include <opm/output/eclipse/VectorItems/connection.hpp>
#include <opm/output/eclipse/VectorItems/intehead.hpp>
#include <opm/output/eclipse/VectorItems/well.hpp>

#include "eclipse/restart_arrays.h"

namespace cutaway::eclipse {
namespace {

namespace fs = std::filesystem;
using Head = Opm::RestartIO::Helpers::VectorItems::intehead;
namespace iwell = Opm::RestartIO::Helpers::VectorItems::IWell;
namespace iconn = Opm::RestartIO::Helpers::VectorItems::IConn;

std::string trimmed(std::string text) {
    text.erase(text.find_last_not_of(' ') + 1);
    return text;
}

std::string well_type(int ecl_type) {
    if (Opm::WellType::producer(ecl_type)) return "producer";
    if (Opm::WellType::water_injector(ecl_type)) return "water_injector";
    if (Opm::WellType::gas_injector(ecl_type)) return "gas_injector";
    if (Opm::WellType::oil_injector(ecl_type)) return "oil_injector";
    return "unknown";
}

std::string well_status(int status) {
    using Status = iwell::Value::Status;
    switch (status) {
        case Status::Open: return "open";
        case Status::Stop: return "stop";
        case Status::Shut: return "shut";
        case Status::Auto: return "auto";
        default: return std::to_string(status);
    }
}

std::size_t head_count(const std::vector<int>& head, std::size_t index) { return std::size_t(std::max(head[index], 0)); }

/// The well's ICON slots (NCWMAX of NICONZ items each), in the order the file lists them.
std::vector<ConnectionAtStep> connections_of(const std::vector<int>& icon, std::size_t well, std::size_t count,
                                             const std::vector<int>& head) {
    const std::size_t items = head_count(head, Head::NICONZ), slots = head_count(head, Head::NCWMAX);
    std::vector<ConnectionAtStep> connections;
    for (std::size_t c = 0; c < count; ++c) {
        const int* item = icon.data() + (well * slots + c) * items;
        // 1-based in the file; a connection status above 0 is open.
        connections.push_back({item[iconn::CellI] - 1, item[iconn::CellJ] - 1, item[iconn::CellK] - 1, item[iconn::ConnStat] > 0});
    }
    return connections;
}

}  // namespace

std::vector<WellAtStep> read_step_wells(Opm::EclIO::ERst& file, const fs::path& unrst, int report_number,
                                        const std::vector<int>& head, bool with_connections) {
    if (head.size() <= std::size_t(Head::NICONZ))
        throw EclipseError({unrst.string(), "INTEHEAD" + step_text(report_number), "a full header",
                            std::to_string(head.size()) + " items"});
    const std::size_t count = head_count(head, Head::NWELLS);
    if (count == 0) return {};
    const std::size_t words_per_well = head_count(head, Head::NZWELZ), items_per_well = head_count(head, Head::NIWELZ);
    const auto& names = step_array<std::string>(file, unrst, "ZWEL", report_number);
    const auto& items = step_array<int>(file, unrst, "IWEL", report_number);
    if (names.size() < count * words_per_well || items.size() < count * items_per_well ||
        items_per_well <= std::size_t(iwell::Status))
        throw EclipseError({unrst.string(), "ZWEL, IWEL" + step_text(report_number),
                            std::to_string(count) + " wells as INTEHEAD counts them",
                            std::to_string(names.size()) + " ZWEL words, " + std::to_string(items.size()) + " IWEL items"});
    const std::vector<int>* icon = nullptr;
    if (with_connections) {
        icon = &step_array<int>(file, unrst, "ICON", report_number);
        const std::size_t needed = count * head_count(head, Head::NCWMAX) * head_count(head, Head::NICONZ);
        if (icon->size() < needed || head_count(head, Head::NICONZ) <= std::size_t(iconn::ConnStat))
            throw EclipseError({unrst.string(), "ICON" + step_text(report_number),
                                std::to_string(needed) + " items (NWELLS x NCWMAX x NICONZ of INTEHEAD)",
                                std::to_string(icon->size())});
    }
    std::vector<WellAtStep> wells;
    for (std::size_t w = 0; w < count; ++w) {
        const int* well = items.data() + w * items_per_well;
        WellAtStep entry{trimmed(names[w * words_per_well]), well_type(well[iwell::WType]), well_status(well[iwell::Status]),
                         well[iwell::IHead] - 1, well[iwell::JHead] - 1, {}};
        if (icon) {
            const int count_in_file = well[iwell::NConn];
            if (count_in_file < 0 || count_in_file > head[Head::NCWMAX])
                throw EclipseError({unrst.string(), "IWEL" + step_text(report_number),
                                    "well " + entry.name + ": 0.." + std::to_string(head[Head::NCWMAX]) + " connections (NCWMAX)",
                                    std::to_string(count_in_file)});
            entry.connections = connections_of(*icon, w, std::size_t(count_in_file), head);
        }
        wells.push_back(std::move(entry));
    }
    return wells;
}

}  // namespace cutaway::eclipse

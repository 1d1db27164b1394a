#pragma once
// The wells of one report step of a UNRST: ZWEL names, IWEL type, status and wellhead, and (on
// request) ICON's connections, laid out as INTEHEAD's NZWELZ, NIWELZ, NICONZ and NCWMAX say.
#include <filesystem>
#include <vector>

#include "eclipse/report_steps.h"

namespace Opm::EclIO {
class ERst;
}

namespace cutaway::eclipse {

/// `head`: the step's INTEHEAD. Throws EclipseError when ZWEL, IWEL (or ICON) hold fewer items
/// than INTEHEAD counts, or a connection count exceeds NCWMAX.
std::vector<WellAtStep> read_step_wells(Opm::EclIO::ERst& file, const std::filesystem::path& unrst, int report_number,
                                        const std::vector<int>& head, bool with_connections);

}  // namespace cutaway::eclipse

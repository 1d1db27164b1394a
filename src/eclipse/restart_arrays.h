#pragma once
// Reading one report step's arrays from an open UNRST through EclIO, each failure an EclipseError
// naming the array and the step (shared by the step list and the wells' reader).
#include <filesystem>
#include <string>
#include <vector>

#include <opm/io/eclipse/ERst.hpp>

#include "eclipse/eclio_access.h"

namespace cutaway::eclipse {

inline std::string step_text(int report_number) { return " at report " + std::to_string(report_number); }

/// Array `name` of report `report_number`; throws EclipseError when the step lacks it or EclIO fails.
template <typename T>
const std::vector<T>& step_array(Opm::EclIO::ERst& file, const std::filesystem::path& unrst, const std::string& name,
                                 int report_number) {
    if (!file.hasArray(name, report_number))
        throw EclipseError({unrst.string(), name + step_text(report_number), "the array in the step", "none"});
    return read_checked(unrst, name + step_text(report_number), "a readable array",
                        [&]() -> const std::vector<T>& { return file.getRestartData<T>(name, report_number); });
}

}  // namespace cutaway::eclipse

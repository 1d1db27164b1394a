#include "eclipse/report_steps.h"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <set>

#include <opm/io/eclipse/ERst.hpp>
#include <opm/output/eclipse/VectorItems/intehead.hpp>

#include "eclipse/eclio_access.h"
#include "eclipse/restart_arrays.h"
#include "eclipse/restart_wells.h"

namespace cutaway::eclipse {
namespace {

namespace fs = std::filesystem;
using Opm::EclIO::eclArrType;
using Opm::EclIO::ERst;
using Head = Opm::RestartIO::Helpers::VectorItems::intehead;

const std::string unrst_expected = "an Eclipse unified restart file (UNRST: SEQNUM, INTEHEAD per report step)";

std::unique_ptr<ERst> open_unrst(const fs::path& unrst) {
    if (!fs::is_regular_file(unrst)) throw EclipseError({unrst.string(), "", "an UNRST file", "no such file"});
    auto file = read_checked(unrst, "", unrst_expected, [&] { return std::make_unique<ERst>(unrst.string()); });
    if (file->numberOfReportSteps() == 0) throw EclipseError({unrst.string(), "SEQNUM", "at least one report step", "none"});
    return file;
}

/// Array `name` of one step per active cell, as floats (REAL or DOUB in the file).
std::vector<float> active_array(ERst& file, const fs::path& unrst, const std::string& name, int report_number,
                                std::size_t active_count) {
    std::vector<float> values;
    const auto arrays = read_checked(unrst, name + step_text(report_number), "a readable step",
                                     [&] { return file.listOfRstArrays(report_number); });
    const auto entry = std::find_if(arrays.begin(), arrays.end(), [&](const auto& a) { return std::get<0>(a) == name; });
    if (entry == arrays.end())
        throw EclipseError({unrst.string(), name + step_text(report_number), "the array in the step", "none"});
    if (std::get<1>(*entry) == eclArrType::DOUB) {
        const auto& doubles = step_array<double>(file, unrst, name, report_number);
        values.assign(doubles.begin(), doubles.end());
    } else if (std::get<1>(*entry) == eclArrType::REAL) {
        values = step_array<float>(file, unrst, name, report_number);
    } else {
        throw EclipseError({unrst.string(), name + step_text(report_number), "a REAL or DOUB array", "another type"});
    }
    if (values.size() != active_count)
        throw EclipseError({unrst.string(), name + step_text(report_number),
                            "one value per active cell of the EGRID (" + std::to_string(active_count) + ")",
                            std::to_string(values.size())});
    return values;
}

}  // namespace

std::string ReportStep::date() const {
    char text[32];
    std::snprintf(text, sizeof text, "%04d-%02d-%02d", year, month, day);
    return text;
}

ReportSteps::ReportSteps(fs::path unrst, const grid::CornerPointGrid& grid, std::size_t memory_limit_bytes)
    : file_(std::move(unrst)), actnum_(grid.actnum()), active_count_(grid.active_count()),
      memory_limit_bytes_(memory_limit_bytes) {
    require_within_memory(file_, "a report step's arrays", read_bytes(), memory_limit_bytes_);
    const std::unique_ptr<ERst> file = open_unrst(file_);
    const grid::GridDims& d = grid.dims();
    std::set<std::string> names;
    for (const int report_number : file->listOfReportStepNumbers()) {
        const auto& head = step_array<int>(*file, file_, "INTEHEAD", report_number);
        if (head.size() <= std::size_t(Head::YEAR))
            throw EclipseError({file_.string(), "INTEHEAD" + step_text(report_number), "a full header",
                                std::to_string(head.size()) + " items"});
        if (head[Head::NX] != d.nx || head[Head::NY] != d.ny || head[Head::NZ] != d.nz ||
            std::size_t(head[Head::NACTIV]) != active_count_)
            throw EclipseError({file_.string(), "INTEHEAD" + step_text(report_number),
                                "a restart of the EGRID's grid: " + std::to_string(d.nx) + " x " + std::to_string(d.ny) +
                                    " x " + std::to_string(d.nz) + " cells, " + std::to_string(active_count_) + " active",
                                std::to_string(head[Head::NX]) + " x " + std::to_string(head[Head::NY]) + " x " +
                                    std::to_string(head[Head::NZ]) + " cells, " +
                                    std::to_string(head[Head::NACTIV]) + " active"});
        if (steps_.empty()) unit_system_ = unit_system_name(head[Head::UNIT]);
        ReportStep step;
        step.index = steps_.size();
        step.report_number = report_number;
        step.day = head[Head::DAY];
        step.month = head[Head::MONTH];
        step.year = head[Head::YEAR];
        if (file->hasArray("DOUBHEAD", report_number)) {
            const auto& doubles = step_array<double>(*file, file_, "DOUBHEAD", report_number);
            if (!doubles.empty()) step.elapsed_days = doubles.front();
        }
        step.wells = read_step_wells(*file, file_, report_number, head, false);
        steps_.push_back(std::move(step));
        const auto arrays = read_checked(file_, "report " + std::to_string(report_number), "a readable step",
                                         [&] { return file->listOfRstArrays(report_number); });
        for (const auto& [name, type, size] : arrays)
            if ((type == eclArrType::REAL || type == eclArrType::DOUB) && std::size_t(size) == active_count_)
                names.insert(name);
    }
    soil_derived_ = names.count("SWAT") && !names.count("SOIL");
    if (soil_derived_) names.insert("SOIL");
    names_.assign(names.begin(), names.end());
}

std::vector<WellAtStep> ReportSteps::wells_with_connections(std::size_t index) const {
    if (index >= steps_.size())
        throw EclipseError({file_.string(), "wells",
                            "a report step index 0.." + std::to_string(steps_.size() - 1) + " (" +
                                std::to_string(steps_.size()) + " steps)",
                            std::to_string(index)});
    const std::unique_ptr<ERst> file = open_unrst(file_);
    const int report_number = steps_[index].report_number;
    const auto& head = step_array<int>(*file, file_, "INTEHEAD", report_number);
    return read_step_wells(*file, file_, report_number, head, true);
}

bool ReportSteps::has_property(const std::string& name) const {
    return std::binary_search(names_.begin(), names_.end(), name);
}

std::size_t ReportSteps::read_bytes() const {
    // The result, and EclIO's copies of at most two arrays (SWAT and SGAS for a derived SOIL; DOUB
    // at worst) with one float copy of each.
    return actnum_.size() * sizeof(float) + 2 * active_count_ * (sizeof(double) + sizeof(float));
}

std::vector<float> ReportSteps::values(const std::string& name, std::size_t index) const {
    if (index >= steps_.size())
        throw EclipseError({file_.string(), name,
                            "a report step index 0.." + std::to_string(steps_.size() - 1) + " (" +
                                std::to_string(steps_.size()) + " steps)",
                            std::to_string(index)});
    if (!has_property(name))
        throw EclipseError({file_.string(), name, "a per-cell restart array (one of the steps' arrays)", "none"});
    require_within_memory(file_, name + " at a report step", read_bytes(), memory_limit_bytes_);
    // A fresh ERst per read: EclIO keeps every array it has read until the file is closed.
    const std::unique_ptr<ERst> file = open_unrst(file_);
    const int report_number = steps_[index].report_number;
    std::vector<float> active;
    if (name == "SOIL" && soil_derived_) {
        active = active_array(*file, file_, "SWAT", report_number, active_count_);
        const std::vector<float> gas = file->hasArray("SGAS", report_number)
                                           ? active_array(*file, file_, "SGAS", report_number, active_count_)
                                           : std::vector<float>(active.size(), 0.0f);
        for (std::size_t c = 0; c < active.size(); ++c) active[c] = 1.0f - active[c] - gas[c];
    } else {
        active = active_array(*file, file_, name, report_number, active_count_);
    }
    return spread_over_cells<float>(active, actnum_);
}

}  // namespace cutaway::eclipse

#include "flow_deck_writer.h"

#include <sstream>

#include "deck_number.h"
#include "flow_fluid_model.h"
#include "grid/grdecl_writer.h"
#include "io/output_batch.h"
#include "io/staged_file.h"

namespace cutaway::generators {
namespace {

/// The arrays flow reads from the included grid file; the generator's FACIES and SWAT steps stay out.
const std::vector<std::string> kDeckProperties = {"PORO", "PERMX", "NTG"};

std::size_t well_count(const WellPlacement& wells) { return wells.injectors.size() + wells.producers.size(); }

void write_runspec(std::ostream& out, const grid::GridDims& dims, const FlowDeckPlan& plan) {
    out << "RUNSPEC\n\nTITLE\n  Waterflood of a cutaway synthetic model\n\n"
        << "DIMENS\n  " << dims.nx << ' ' << dims.ny << ' ' << dims.nz << " /\n\n"
        << "OIL\nWATER\n\nMETRIC\n\n"
        << "TABDIMS\n-- saturation tables, PVT tables, rows per saturation table, rows per PVT table\n  1 1 "
        << flow_fluids::relperm_rows + 1 << " 20 /\n\n"
        << "WELLDIMS\n-- wells, connections per well, groups, wells per group\n  " << well_count(plan.wells) << ' '
        << dims.nz << " 1 " << well_count(plan.wells) << " /\n\n"
        << "EQLDIMS\n  1 /\n\n"
        << "START\n  1 'JAN' 2025 /\n\nUNIFOUT\n\n";
}

void write_grid(std::ostream& out, const std::string& grid_file_name) {
    out << "GRID\n\nINIT\n\nINCLUDE\n  '" << grid_file_name << "' /\n\n"
        << "COPY\n  PERMX PERMY /\n  PERMX PERMZ /\n/\n\n"
        << "MULTIPLY\n  PERMZ " << deck_number(flow_fluids::vertical_permeability_ratio) << " /\n/\n\n";
}

void write_solution(std::ostream& out, const FlowSchedule& s) {
    out << "SOLUTION\n\nRPTSOL\n-- the initial state is report step 0 of the restart file\n  'RESTART=2' /\n\nEQUIL\n-- datum depth (m), pressure there (bar), oil-water contact (m, below the model), "
           "Pcow there\n  "
        << deck_number(s.datum_depth_m) << ' ' << deck_number(s.datum_pressure_bar) << ' '
        << deck_number(s.water_contact_depth_m) << " 0 /\n\n";
}

void write_summary(std::ostream& out) {
    out << "SUMMARY\n\nFOPR\nFWPR\nFWIR\nFWCT\nFPR\nWBHP\n/\nWWIR\n/\nWOPR\n/\n\n";
}

/// COMPDAT lines of `well`: one per run of consecutive active layers (1-based, inclusive).
void write_completions(std::ostream& out, const DeckWell& well) {
    const std::vector<int>& layers = well.column.layers;
    for (std::size_t first = 0; first < layers.size();) {
        std::size_t last = first;
        while (last + 1 < layers.size() && layers[last + 1] == layers[last] + 1) ++last;
        out << "  '" << well.name << "' " << well.column.i + 1 << ' ' << well.column.j + 1 << ' ' << layers[first] + 1
            << ' ' << layers[last] + 1 << " 'OPEN' 1* 1* " << deck_number(flow_fluids::wellbore_diameter_m) << " /\n";
        first = last + 1;
    }
}

void write_schedule(std::ostream& out, const FlowDeckPlan& plan) {
    const WellPlacement& w = plan.wells;
    const FlowSchedule& s = plan.schedule;
    out << "SCHEDULE\n\nRPTRST\n  'BASIC=2' /\n\nWELSPECS\n-- name, group, I, J, reference depth (top completion), phase\n";
    for (const DeckWell& well : w.injectors)
        out << "  '" << well.name << "' 'FLOOD' " << well.column.i + 1 << ' ' << well.column.j + 1 << " 1* 'WATER' /\n";
    for (const DeckWell& well : w.producers)
        out << "  '" << well.name << "' 'FLOOD' " << well.column.i + 1 << ' ' << well.column.j + 1 << " 1* 'OIL' /\n";
    out << "/\n\nCOMPDAT\n-- name, I, J, K first, K last, open, saturation table, factor, diameter (m)\n";
    for (const DeckWell& well : w.injectors) write_completions(out, well);
    for (const DeckWell& well : w.producers) write_completions(out, well);
    out << "/\n\nWCONINJE\n-- name, water, open, rate control, surface rate (sm3/day), reservoir rate, BHP limit (bar)\n";
    for (std::size_t n = 0; n < w.injectors.size(); ++n)
        out << "  '" << w.injectors[n].name << "' 'WATER' 'OPEN' 'RATE' " << deck_number(s.injection_rate_sm3_day[n])
            << " 1* " << deck_number(s.injector_bhp_limit_bar[n]) << " /\n";
    out << "/\n\nWCONPROD\n-- name, open, BHP control, 5 rate limits defaulted, BHP (bar)\n";
    for (std::size_t n = 0; n < w.producers.size(); ++n)
        out << "  '" << w.producers[n].name << "' 'OPEN' 'BHP' 5* " << deck_number(s.producer_bhp_bar[n]) << " /\n";
    out << "/\n\nTSTEP\n-- " << s.report_steps << " report steps of " << s.report_step_days << " days\n  "
        << s.report_steps << '*' << s.report_step_days << " /\n\nEND\n";
}

}  // namespace

FlowDeckPlan plan_flow_deck(const grid::CornerPointGrid& grid) {
    FlowDeckPlan plan;
    plan.wells = place_wells(grid);
    plan.schedule = plan_flow_schedule(grid, plan.wells);
    return plan;
}

std::string flow_deck_text(const grid::GridDims& dims, const FlowDeckPlan& plan, const std::string& grid_file_name,
                           const std::vector<std::string>& header_comments) {
    std::ostringstream out;
    for (const std::string& line : header_comments) out << "-- " << line << '\n';
    for (const std::string& line : describe(plan)) out << "-- " << line << '\n';
    out << '\n';
    write_runspec(out, dims, plan);
    write_grid(out, grid_file_name);
    out << "PROPS\n\n" << flow_fluids::props_section_text();
    write_solution(out, plan.schedule);
    write_summary(out);
    write_schedule(out, plan);
    return out.str();
}

FlowDeckFiles flow_deck_files(const std::filesystem::path& directory, const std::string& case_name) {
    return {directory / (case_name + ".DATA"), directory / (case_name + ".GRDECL")};
}

void write_flow_deck(const FlowDeckFiles& files, const grid::CornerPointGrid& grid, const FlowDeckPlan& plan,
                     const std::vector<std::string>& header_comments) {
    const std::filesystem::path directory = files.data.parent_path();
    std::error_code error;
    const bool created = std::filesystem::create_directory(directory, error);
    if (error) io::fail_output(directory, error.value());
    grid::GrdeclWriteOptions options;
    options.header_comments = header_comments;
    options.only_properties = kDeckProperties;
    bool grid_written = false;
    try {  // a deck is whole or absent: the grid file goes when the DATA file cannot be written
        grid::write_grdecl(files.grid, grid, options);
        grid_written = true;
        io::write_file(files.data, flow_deck_text(grid.dims(), plan, files.grid.filename().string(), header_comments));
    } catch (...) {
        if (grid_written) std::filesystem::remove(files.grid, error);
        if (created) std::filesystem::remove(directory, error);
        throw;
    }
}

std::vector<std::string> describe(const FlowDeckPlan& plan) {
    const WellPlacement& w = plan.wells;
    const FlowSchedule& s = plan.schedule;
    std::vector<std::string> lines;
    const auto columns = [](const std::vector<DeckWell>& wells) {
        std::string text;
        for (const DeckWell& well : wells)
            text += (text.empty() ? "" : ", ") + well.name + " (" + std::to_string(well.column.i) + " " +
                    std::to_string(well.column.j) + ")";
        return text;
    };
    lines.push_back("deck injectors (column i j, 0-based) = " + columns(w.injectors));
    lines.push_back("deck producers (column i j, 0-based) = " + columns(w.producers));
    lines.push_back("deck down-dip direction = " + deck_number(w.down_dip_x) + " " + deck_number(w.down_dip_y) +
                    " (dip " + deck_number(w.dip) + " m/m)");
    lines.push_back("deck pore volume = " + deck_number(s.pore_volume_m3) + " m3");
    double rate = 0;
    for (double q : s.injection_rate_sm3_day) rate += q;
    lines.push_back("deck injection = " + deck_number(rate) + " sm3/day (estimated capacity " +
                    deck_number(s.estimated_capacity_m3_day) + " m3/day)");
    lines.push_back("deck report steps = " + std::to_string(s.report_steps) + " x " +
                    std::to_string(s.report_step_days) + " days");
    return lines;
}

}  // namespace cutaway::generators

// `cutaway inspect MODEL.grdecl [MORE.grdecl...] | preset:NAME | CASE.EGRID [--json]
//  [--cells-csv FILE [--property NAME]... [--time-step K]]`
#include <charconv>
#include <chrono>
#include <ostream>
#include <iostream>
#include <map>
#include <set>

#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "app_core/model_source.h"
#include "app_core/option_checks.h"
#include "app_core/property_statistics.h"
#include "app_core/render_options.h"
#include "eclipse/eclipse_error.h"
#include "eclipse/init_reader.h"
#include "eclipse/simulator_case.h"
#include "grid/grid_summary.h"
#include "grid/primary_selection.h"
#include "io/output_batch.h"

namespace cutaway::app {
namespace {

struct InspectOptions {
    std::vector<std::string> files;
    bool json = false;
    std::string cells_csv;
    std::vector<std::string> properties;  ///< one CSV column each
    int time_step = -1;                   ///< report step of the dynamic ones (-1: 0)
    double memory_limit_gb = default_memory_limit_gib;
};

/// The values of each --property at --time-step (static properties ignore the step), read onto
/// the grid first where the model is a simulator case. Throws std::invalid_argument naming the
/// option for an unknown property or step.
std::vector<PropertyChoice> property_columns(LoadedModel& model, const InspectOptions& options) {
    std::vector<PropertyChoice> columns;
    for (const std::string& name : options.properties) {
        hold_property(model, name, options.time_step, gib_to_bytes(options.memory_limit_gb));
        RenderOptions chosen;
        chosen.property = name;
        chosen.step = model.grid.step_count(name) > 0 ? options.time_step : -1;
        columns.push_back(choose_property(model.grid, chosen));
    }
    return columns;
}

/// The shortest text that reads back as `value` (a float property value as the float it is).
template <typename Real>
std::string shortest(Real value) {
    char buffer[32];
    return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}

void write_cells_csv(std::ostream& out, const grid::CornerPointGrid& grid, const std::vector<PropertyChoice>& columns) {
    out << "i,j,k,volume,cx,cy,cz";
    for (const PropertyChoice& column : columns) out << ',' << column.name;
    out << '\n';
    const grid::GridDims& d = grid.dims();
    for (int k = 0; k < d.nz; ++k)
        for (int j = 0; j < d.ny; ++j)
            for (int i = 0; i < d.nx; ++i) {
                if (!grid.active(d.cell_index(i, j, k))) continue;
                const grid::CellCorners corners = grid::cell_corners(grid, i, j, k);
                const grid::Point3 c = grid::cell_centre(corners);
                out << i << ',' << j << ',' << k << ',' << shortest(grid::cell_volume(corners)) << ','
                    << shortest(c.x) << ',' << shortest(c.y) << ',' << shortest(c.z);
                for (const PropertyChoice& column : columns)
                    out << ',' << shortest(column.values()[d.cell_index(i, j, k)]);
                out << '\n';
            }
}

/// The report steps (index, the simulator's number, date, days, wells) of a simulator case.
nlohmann::json report_steps_json(const eclipse::ReportSteps& steps) {
    nlohmann::json list = nlohmann::json::array();
    for (const eclipse::ReportStep& step : steps.steps()) {
        nlohmann::json wells = nlohmann::json::array();
        for (const eclipse::WellAtStep& well : step.wells)
            wells.push_back({{"name", well.name}, {"type", well.type}, {"status", well.status}});
        list.push_back({{"index", step.index}, {"report", step.report_number}, {"date", step.date()},
                        {"elapsed_days", step.elapsed_days}, {"wells", wells}});
    }
    return list;
}

/// Every well of any step, in order of first appearance, with its type, wellhead (0-based) and
/// connection count at the last step listing it (ICON read for the steps that list a well last).
nlohmann::json wells_json(const eclipse::ReportSteps& steps) {
    std::vector<std::string> order;
    std::map<std::string, std::size_t> last_step;
    for (const eclipse::ReportStep& step : steps.steps())
        for (const eclipse::WellAtStep& well : step.wells) {
            if (!last_step.count(well.name)) order.push_back(well.name);
            last_step[well.name] = step.index;
        }
    std::map<std::string, nlohmann::json> described;
    std::set<std::size_t> read;
    for (const auto& [name, step] : last_step) {
        if (!read.insert(step).second) continue;
        for (const eclipse::WellAtStep& well : steps.wells_with_connections(step))
            if (last_step[well.name] == step)
                described[well.name] = {{"name", well.name}, {"type", well.type}, {"head", {well.head_i, well.head_j}},
                                        {"connections", well.connections.size()}};
    }
    nlohmann::json wells = nlohmann::json::array();
    for (const std::string& name : order) wells.push_back(described[name]);
    return wells;
}

/// Range and percentiles of every real property held, and of every dynamic one at --time-step
/// (read here for a simulator case: one array each), keyed by name ("NAME@step K" for dynamic ones).
nlohmann::json property_ranges(LoadedModel& model, const InspectOptions& options) {
    nlohmann::json ranges = nlohmann::json::object();
    if (model.init_file) {  // a case reads INIT arrays on demand: the report lists them all when they fit
        const std::size_t limit = gib_to_bytes(options.memory_limit_gb);
        try {
            eclipse::add_init_properties(model.grid, *model.init_file, eclipse::memory_left(model.grid, limit), std::nullopt);
        } catch (const eclipse::EclipseError& e) {
            model.warnings.push_back(std::string("static arrays not summarised: ") + e.what());
        }
    }
    const grid::CornerPointGrid& grid = model.grid;
    for (const std::string& name : grid.property_names())
        ranges[name] = property_statistics(grid, *grid.property(name), name);
    const int step = std::max(options.time_step, 0);
    for (const std::string& name : grid.dynamic_property_names()) {
        hold_property(model, name, step, gib_to_bytes(options.memory_limit_gb));
        if (const std::vector<float>* values = grid.dynamic_property(name, std::size_t(step)))
            ranges[name + "@step " + std::to_string(step)] = property_statistics(grid, *values, name);
    }
    return ranges;
}

nlohmann::json summary_json(const InspectOptions& options, const LoadedModel& model, const grid::GridSummary& s,
                            double summary_ms, const nlohmann::json& ranges) {
    const grid::CornerPointGrid& grid = model.grid;
    nlohmann::json j;
    j["files"] = options.files;
    j["model"] = model.description;
    j["dims"] = {s.dims.nx, s.dims.ny, s.dims.nz};
    j["cells"] = s.cells;
    j["active_cells"] = s.active_cells;
    j["faces"] = {{"interior", s.faces.interior}, {"fault", s.faces.fault}, {"shell", s.faces.shell}};
    j["face_tolerance"] = s.face_tolerance;
    j["volume"] = {{"total", s.total_active_volume}, {"min", s.min_active_volume}, {"max", s.max_active_volume}};
    j["pinched_cells"] = s.pinched_cells;
    j["inverted_cells"] = s.inverted_cells;
    j["overlapping_cells"] = s.overlapping_cells;
    j["depth_direction"] = s.depth_direction > 0 ? "down" : "up";
    if (!s.bounds.empty())
        j["bounds"] = {{"min", {s.bounds.min.x, s.bounds.min.y, s.bounds.min.z}},
                       {"max", {s.bounds.max.x, s.bounds.max.y, s.bounds.max.z}}};
    j["properties"] = grid.property_names();
    j["int_properties"] = grid.int_property_names();
    nlohmann::json dynamic = nlohmann::json::object();
    for (const auto& name : grid.dynamic_property_names()) dynamic[name] = grid.step_count(name);
    j["dynamic_properties"] = dynamic;
    const grid::GridMetadata& meta = grid.metadata();
    j["mapaxes"] = meta.mapaxes ? nlohmann::json(*meta.mapaxes) : nlohmann::json(nullptr);
    j["grid_unit"] = meta.grid_unit;
    j["map_units"] = meta.map_units;
    j["unit_system"] = meta.unit_system;
    j["gdorient"] = meta.gdorient;
    j["zcorn_layout"] = s.zcorn_compact ? "compact" : "full";
    j["memory"] = {{"geometry_bytes", s.geometry_bytes},
                   {"property_bytes", s.property_bytes},
                   {"geometry_bytes_per_cell", s.cells ? double(s.geometry_bytes) / double(s.cells) : 0.0}};
    j["property_ranges"] = ranges;
    if (model.report_steps) {
        j["report_steps"] = report_steps_json(*model.report_steps);
        j["wells"] = wells_json(*model.report_steps);
        j["soil_derived"] = model.report_steps->soil_derived();
    }
    j["times_ms"] = {{"load", 1e3 * model.load_seconds}, {"summary", summary_ms}};
    j["warnings"] = model.warnings;
    return j;
}

void print_text(std::ostream& out, const nlohmann::json& j) {
    out << "files:        ";
    for (const auto& f : j["files"]) out << f.get<std::string>() << ' ';
    out << "\ndimensions:   " << j["dims"][0] << " x " << j["dims"][1] << " x " << j["dims"][2] << " = " << j["cells"]
        << " cells\nactive cells: " << j["active_cells"] << "\nfaces:        interior " << j["faces"]["interior"]
        << ", fault " << j["faces"]["fault"] << ", shell " << j["faces"]["shell"] << " (tolerance "
        << j["face_tolerance"] << ")\nvolume:       total " << j["volume"]["total"] << ", min " << j["volume"]["min"]
        << ", max " << j["volume"]["max"] << "\nshapes:       " << j["pinched_cells"] << " pinched, "
        << j["inverted_cells"] << " inverted, " << j["overlapping_cells"]
        << " overlapping the layer above (kept as written; OPM cuts them)\n";
    if (j.contains("bounds")) out << "bounds:       " << j["bounds"]["min"].dump() << " .. " << j["bounds"]["max"].dump() << '\n';
    out << "properties:   " << j["properties"].dump() << " integer " << j["int_properties"].dump() << " dynamic "
        << j["dynamic_properties"].dump() << "\nunits:        grid '" << j["grid_unit"].get<std::string>() << "', map '"
        << j["map_units"].get<std::string>() << "', system '" << j["unit_system"].get<std::string>() << "', mapaxes "
        << j["mapaxes"].dump() << "\nmemory:       "
        << j["memory"]["geometry_bytes"] << " bytes geometry (" << j["memory"]["geometry_bytes_per_cell"]
        << " per cell, ZCORN " << j["zcorn_layout"].get<std::string>() << "), " << j["memory"]["property_bytes"]
        << " bytes properties\ntimes:        load " << j["times_ms"]["load"] << " ms, summary "
        << j["times_ms"]["summary"] << " ms\n";
    if (!j["property_ranges"].empty())
        out << "ranges:       active cells (render's colour range is p2..p98)\n" << property_statistics_text(j["property_ranges"]);
    if (j.contains("report_steps") && !j["report_steps"].empty())
        out << "report steps: " << j["report_steps"].size() << ", " << j["report_steps"].front()["date"].get<std::string>()
            << " (report " << j["report_steps"].front()["report"] << ") .. "
            << j["report_steps"].back()["date"].get<std::string>() << " (report " << j["report_steps"].back()["report"]
            << ")\nwells:        " << j["wells"].size() << '\n';
    for (const auto& w : j["warnings"]) out << "warning: " << w.get<std::string>() << '\n';
}

/// Refuses NaN or infinity in an active cell of any real property (every step of a dynamic one),
/// as `render` refuses the property it colours by: a report must not call such a model usable.
void refuse_non_finite_properties(const grid::CornerPointGrid& grid) {
    for (const std::string& name : grid.property_names()) grid::check_finite_active(grid, *grid.property(name), name);
    for (const std::string& name : grid.dynamic_property_names())
        for (std::size_t step = 0; step < grid.step_count(name); ++step)
            if (const std::vector<float>* values = grid.dynamic_property(name, step))  // a case holds the steps read
                grid::check_finite_active(grid, *values, name + " step " + std::to_string(step));
}

int run_inspect(const InspectOptions& options) {
    const std::vector<io::NamedFile> outputs{{"--cells-csv", options.cells_csv}};
    refuse_overwrites(model_input_files(options.files), outputs);
    using clock = std::chrono::steady_clock;
    LoadedModel model = load_model(options.files, gib_to_bytes(options.memory_limit_gb), std::nullopt, outputs);
    // Ranges first: they read arrays onto the grid, which the columns then point into.
    const nlohmann::json ranges = property_ranges(model, options);
    const std::vector<PropertyChoice> columns = property_columns(model, options);
    const grid::CornerPointGrid& grid = model.grid;
    refuse_non_finite_properties(grid);
    const auto t1 = clock::now();
    const grid::GridSummary summary = grid::summarize(grid);
    const double summary_ms = std::chrono::duration<double, std::milli>(clock::now() - t1).count();

    const nlohmann::json j = summary_json(options, model, summary, summary_ms, ranges);
    // The CSV first: a failed write ends the command before a report that would look like success.
    if (!options.cells_csv.empty())
        io::write_stream(options.cells_csv, [&](std::ostream& out) { write_cells_csv(out, grid, columns); });
    if (options.json)
        std::cout << j.dump(2) << '\n';
    else
        print_text(std::cout, j);
    return 0;
}

}  // namespace

CommandAction add_inspect_command(CLI::App& app) {
    auto options = std::make_shared<InspectOptions>();
    CLI::App* cmd = app.add_subcommand("inspect", "Load GRDECL file(s) onto one grid, or generate a preset, and report "
                                                  "dimensions, active cells, faces by class and volumes");
    cmd->add_option("model", options->files,
                    "GRDECL file(s): the grid, then any property files; preset:NAME; or a simulator case CASE.EGRID "
                    "(or CASE) with CASE.INIT and CASE.UNRST beside it")
        ->required()
        ->check(utf8_text());
    cmd->add_flag("--json", options->json, "Print the report as JSON");
    cmd->add_option("--cells-csv", options->cells_csv,
                    "Write i,j,k,volume,cx,cy,cz per active cell (0-based ijk), then one column per --property")
        ->check(writable_output());
    cmd->add_option("--property", options->properties, "a --cells-csv column of this property's values (repeatable)")
        ->check(utf8_text());
    cmd->add_option("--time-step,--step", options->time_step,
                    "report step of the dynamic --property columns: the K-th in the file, 0-based (default 0)")
        ->check(finite_in(0, 1e6));
    add_memory_limit_option(*cmd, options->memory_limit_gb, "grids (file text and arrays)");
    return [options] { return run_inspect(*options); };
}

}  // namespace cutaway::app

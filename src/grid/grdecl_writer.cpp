#include "grid/grdecl_writer.h"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <stdexcept>

#include "io/output_batch.h"

namespace cutaway::grid {
namespace {

/// Writes one keyword's values, folding runs of equal values into `N*value`, a few per line.
class ValueWriter {
public:
    ValueWriter(std::ostream& out, const char* keyword, int items_per_line)
        : out_(out), items_per_line_(items_per_line) {
        out_ << keyword << '\n';
    }
    ~ValueWriter() = default;

    template <typename T>
    void add(T value) {
        if (run_ > 0 && value_text(value) == run_text_) {
            ++run_;
            return;
        }
        flush_run();
        run_text_ = value_text(value);
        run_ = 1;
    }

    void finish() {
        flush_run();
        if (on_line_ > 0) out_ << '\n';
        out_ << "/\n\n";
    }

private:
    template <typename T>
    static std::string value_text(T value) {
        char buffer[64];
        // Shortest text that reads back to the same value (std::to_chars without precision).
        const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
        return std::string(buffer, result.ptr);
    }

    void flush_run() {
        if (run_ == 0) return;
        out_ << ' ';
        if (run_ > 1) out_ << run_ << '*';
        out_ << run_text_;
        if (++on_line_ == items_per_line_) {
            out_ << '\n';
            on_line_ = 0;
        }
        run_ = 0;
    }

    std::ostream& out_;
    int items_per_line_;
    int on_line_ = 0;
    std::size_t run_ = 0;
    std::string run_text_;
};

template <typename T>
void write_array(std::ostream& out, const char* keyword, const std::vector<T>& values) {
    ValueWriter writer(out, keyword, 8);
    for (const T& v : values) writer.add(v);
    writer.finish();
}

bool written(const GrdeclWriteOptions& options, const std::string& name) {
    return !options.only_properties ||
           std::find(options.only_properties->begin(), options.only_properties->end(), name) !=
               options.only_properties->end();
}

}  // namespace

void write_grdecl(std::ostream& out, const CornerPointGrid& grid, const GrdeclWriteOptions& options) {
    for (const std::string& line : options.header_comments) out << "-- " << line << '\n';
    if (!options.header_comments.empty()) out << '\n';

    const GridMetadata& meta = grid.metadata();
    if (!meta.map_units.empty()) out << "MAPUNITS\n'" << meta.map_units << "' /\n\n";
    if (meta.mapaxes) {
        ValueWriter writer(out, "MAPAXES", 2);
        for (double v : *meta.mapaxes) writer.add(v);
        writer.finish();
    }
    if (!meta.grid_unit.empty()) out << "GRIDUNIT\n'" << meta.grid_unit << "' /\n\n";
    const GridDims& d = grid.dims();
    out << "SPECGRID\n  " << d.nx << ' ' << d.ny << ' ' << d.nz << " 1 F /\n\n";
    if (!meta.gdorient.empty()) {
        out << "GDORIENT\n ";
        for (const std::string& item : meta.gdorient) out << ' ' << item;
        out << " /\n\n";
    }

    {
        ValueWriter writer(out, "COORD", 6);
        for (double v : grid.coord()) writer.add(v);
        writer.finish();
    }
    {
        ValueWriter writer(out, "ZCORN", 8);
        const ZcornStore& zcorn = grid.zcorn();
        for (std::size_t n = 0; n < d.zcorn_value_count(); ++n) writer.add(zcorn.value(n));
        writer.finish();
    }
    {
        ValueWriter writer(out, "ACTNUM", 20);
        for (std::uint8_t a : grid.actnum()) writer.add(int(a));
        writer.finish();
    }
    for (const std::string& name : grid.property_names())
        if (written(options, name)) write_array(out, name.c_str(), *grid.property(name));
    for (const std::string& name : grid.int_property_names())
        if (written(options, name)) write_array(out, name.c_str(), *grid.int_property(name));
    for (const std::string& name : grid.dynamic_property_names()) {
        if (!written(options, name)) continue;
        out << "-- " << name << ": " << grid.step_count(name) << " time steps, one keyword each, in order\n";
        for (std::size_t step = 0; step < grid.step_count(name); ++step)
            write_array(out, name.c_str(), *grid.dynamic_property(name, step));
    }
}

void write_grdecl(const std::filesystem::path& path, const CornerPointGrid& grid, const GrdeclWriteOptions& options) {
    io::write_stream(path, [&](std::ostream& out) { write_grdecl(out, grid, options); });
}

}  // namespace cutaway::grid

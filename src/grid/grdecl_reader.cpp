#include "grid/grdecl_reader.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <set>

#include "grid/grdecl_lexer.h"
#include "io/input_file.h"
#include "io/path_text.h"

namespace cutaway::grid {
namespace {

// Keywords that take no data and no '/' terminator.
const std::set<std::string_view> no_data_keywords = {
    "NOECHO", "ECHO", "GRID", "EDIT", "PROPS", "REGIONS", "SOLUTION", "SUMMARY", "SCHEDULE", "RUNSPEC", "END",
    "NONNC", "NEWTRAN", "OLDTRAN", "NOGGF", "INIT", "NOSIM"};
// Grid keywords: one per deck; an unknown keyword's data never runs into one of these.
const std::set<std::string_view> grid_keywords = {"SPECGRID", "DIMENS", "COORD", "ZCORN", "ACTNUM",
                                                  "MAPAXES", "GRIDUNIT", "MAPUNITS", "GDORIENT", "INCLUDE"};
// Per-cell real properties.
const std::set<std::string_view> float_property_keywords = {
    "PORO", "PERMX", "PERMY", "PERMZ", "NTG", "PORV", "MULTX", "MULTY", "MULTZ", "MULTPV",
    "SWL", "SWCR", "SWU", "SGL", "SGCR", "SGU", "SOWCR", "SOGCR", "TEMPI"};
// Per-cell solution properties: every occurrence adds a time step.
const std::set<std::string_view> dynamic_property_keywords = {"SWAT", "SGAS", "SOIL", "PRESSURE", "RS", "RV"};

bool is_integer_property(std::string_view name) {
    return name == "FACIES" || (name.size() > 3 && name.substr(name.size() - 3) == "NUM");
}

bool looks_like_keyword(const Token& token) {
    if (token.kind != TokenKind::word || !token.first_on_line || token.text.empty() || token.text.size() > 8)
        return false;
    if (!(token.text[0] >= 'A' && token.text[0] <= 'Z')) return false;
    return std::all_of(token.text.begin(), token.text.end(), [](char c) {
        return (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '+' || c == '-';
    });
}

std::string quote(std::string_view text) {
    constexpr std::size_t shown = 40;
    std::string s(text.substr(0, shown));
    for (char& c : s)
        if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) c = '?';
    return "'" + s + (text.size() > shown ? "...'" : "'");
}

/// Printable ASCII (no control characters, no bytes above 126): what keywords and the short
/// strings of GRIDUNIT, MAPUNITS and GDORIENT may hold, so no other byte reaches a report.
bool is_printable_ascii(std::string_view text) {
    return std::all_of(text.begin(), text.end(), [](char c) {
        const auto byte = static_cast<unsigned char>(c);
        return byte >= 32 && byte <= 126;
    });
}

/// A keyword as messages show it: at most 40 characters (a 20 MB "keyword" is not echoed whole).
std::string shown_keyword(std::string_view keyword) {
    constexpr std::size_t shown = 40;
    return keyword.size() > shown ? std::string(keyword.substr(0, shown)) + "..." : std::string(keyword);
}

std::string describe(const Token& token) {
    switch (token.kind) {
        case TokenKind::end: return "end of file";
        case TokenKind::slash: return "'/'";
        case TokenKind::quoted: return "quoted string " + quote(token.text);
        case TokenKind::word: break;
    }
    return quote(token.text);
}

std::optional<double> parse_double(std::string_view text) {
    double value = 0;
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error == std::errc() && end == text.data() + text.size()) return value;
    // Fortran writers use D for the exponent (1.5D+03).
    const std::size_t d = text.find_first_of("dD");
    if (d == std::string_view::npos || text.size() > 64) return std::nullopt;
    std::string copy(text);
    copy[d] = 'E';
    auto [end2, error2] = std::from_chars(copy.data(), copy.data() + copy.size(), value);
    if (error2 == std::errc() && end2 == copy.data() + copy.size()) return value;
    return std::nullopt;
}

std::optional<float> parse_float(std::string_view text) {
    float value = 0;
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error == std::errc() && end == text.data() + text.size()) return value;
    const auto wide = parse_double(text);  // D exponents, or out of float range
    if (wide) return float(*wide);
    return std::nullopt;
}

std::optional<long long> parse_integer(std::string_view text) {
    long long value = 0;
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error == std::errc() && end == text.data() + text.size()) return value;
    return std::nullopt;
}

std::string byte_text(double bytes) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.3g GB", bytes / 1e9);
    return buffer;
}

/// A coordinate in messages (%g).
std::string number_text(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", value);
    return buffer;
}

}  // namespace

/// Which values of a whole-grid array the reader keeps: all, or those of the block's cells.
class CellFilter {
public:
    CellFilter(const GridDims& dims, const std::optional<IjkBox>& block) : dims_(dims), block_(block) {}
    /// Cells kept (the block's, or the grid's).
    GridDims kept_dims() const { return block_ ? block_->dims() : dims_; }
    /// Whether per-cell value `n` (Eclipse order) is kept.
    bool keeps_cell(std::size_t n) const { return !block_ || block_->contains(cell_ijk(dims_, n)); }
    /// Whether ZCORN value `n` (Eclipse order: 2NX per row, 2NY rows per plane, 2NZ planes) is kept.
    bool keeps_corner(std::size_t n) const {
        if (!block_) return true;
        const std::size_t row_length = 2 * std::size_t(dims_.nx), rows = n / row_length;
        return block_->contains({int(n % row_length / 2), int(rows / 2 % std::size_t(dims_.ny)),
                                 int(rows / (4 * std::size_t(dims_.ny)))});
    }
    /// Calls keep(first kept index) for each kept value of a run of `count` values from `first`.
    template <typename Keeps, typename Keep>
    static void each_kept(std::size_t first, std::size_t count, Keeps&& keeps, Keep&& keep) {
        for (std::size_t n = first; n < first + count; ++n)
            if (keeps(n)) keep();
    }

private:
    GridDims dims_;
    std::optional<IjkBox> block_;
};

struct GrdeclReader::State {
    GrdeclReadOptions options;
    std::optional<GridDims> dims;
    std::vector<double> coord;
    std::optional<ZcornStore> zcorn;
    std::vector<std::uint8_t> actnum;
    GridMetadata metadata;
    std::map<std::string, std::vector<float>> float_properties;
    std::map<std::string, std::vector<std::int32_t>> int_properties;
    std::map<std::string, std::vector<std::vector<float>>> dynamic_properties;
    std::vector<std::string> warnings;
    std::vector<std::filesystem::path> include_stack;  // files being read, outermost first
    std::string first_file;
    std::size_t bytes_reserved = 0;
    std::size_t warnings_not_shown = 0;
    bool stop_at_dims = false;  ///< read_grdecl_dims: stop once the dimensions are known
};

namespace {

/// Reads one file's (or text's) keywords into the shared state.
class KeywordParser {
public:
    KeywordParser(GrdeclReader::State& state, std::string_view text, std::string file, std::filesystem::path base_dir)
        : state_(state), lexer_(text), file_(std::move(file)), base_dir_(std::move(base_dir)) {}

    void run() {
        for (;;) {
            if (state_.stop_at_dims && state_.dims) return;
            const Token token = next_token();
            if (token.kind == TokenKind::end) return;
            if (token.kind == TokenKind::slash) {
                warn(token.line, "stray '/' outside any keyword ignored");
                continue;
            }
            if (token.kind == TokenKind::quoted || !looks_like_keyword_text(token.text))
                fail(token.line, "", "a keyword", describe(token));
            if (!is_printable_ascii(token.text))
                fail(token.line, "", "a keyword of ASCII letters and digits", describe(token));
            keyword_ = std::string(token.text);
            keyword_line_ = token.line;
            dispatch();
            keyword_.clear();
        }
    }

private:
    /// The next token; a quote left open at the end of its line is an error.
    Token next_token() {
        const Token token = lexer_.next();
        if (lexer_.unterminated_quote())
            fail(token.line, "a closing quote on the same line", "an unterminated string " + quote(token.text));
        return token;
    }

    static bool looks_like_keyword_text(std::string_view text) {
        return !text.empty() && ((text[0] >= 'A' && text[0] <= 'Z') || (text[0] >= 'a' && text[0] <= 'z'));
    }

    [[noreturn]] void fail(int line, const std::string& keyword, std::string expected, std::string found) const {
        throw GrdeclError({file_, line, shown_keyword(keyword), std::move(expected), std::move(found)});
    }
    [[noreturn]] void fail(int line, std::string expected, std::string found) const {
        fail(line, keyword_, std::move(expected), std::move(found));
    }
    /// Keeps the first max_warnings notes and one last line counting the rest (a file of 500,000
    /// unknown keywords printed 42 MB of warnings).
    void warn(int line, const std::string& text) {
        constexpr std::size_t max_warnings = 100;
        std::vector<std::string>& warnings = state_.warnings;
        if (warnings.size() < max_warnings) {
            warnings.push_back(file_ + ":" + std::to_string(line) + ": " + text);
            return;
        }
        ++state_.warnings_not_shown;
        const std::string summary = std::to_string(state_.warnings_not_shown) + " more warnings not shown";
        if (warnings.size() == max_warnings) warnings.push_back(summary);
        else warnings.back() = summary;
    }

    void dispatch() {
        const std::string& k = keyword_;
        if (no_data_keywords.count(k)) return;
        if (k == "SPECGRID" || k == "DIMENS") return read_dims();
        if (k == "COORD") return read_coord();
        if (k == "ZCORN") return read_zcorn();
        if (k == "ACTNUM") return read_actnum();
        if (k == "MAPAXES") return read_mapaxes();
        if (k == "GRIDUNIT") {
            state_.metadata.grid_unit = read_string_items().front();
            return;
        }
        if (k == "MAPUNITS") {
            state_.metadata.map_units = read_string_items().front();
            return;
        }
        if (k == "GDORIENT") {
            state_.metadata.gdorient = read_string_items();
            return;
        }
        if (k == "INCLUDE") return read_include();
        if (float_property_keywords.count(k) || dynamic_property_keywords.count(k) || is_integer_property(k))
            return read_known_property();
        read_unknown();
    }

    // ---- value lists -------------------------------------------------------------------

    /// Reads the items up to '/', calling sink(value_text, count) for each; exactly `expected`
    /// values (after expanding N*value) must be present.
    template <typename Sink>
    void read_values(std::size_t expected, Sink&& sink) {
        std::size_t found = 0;
        for (;;) {
            const Token token = next_token();
            if (token.kind == TokenKind::slash) break;
            if (token.kind == TokenKind::end)
                fail(token.line, std::to_string(expected) + " values and a '/' terminator",
                     std::to_string(found) + " values, then end of file");
            if (token.kind == TokenKind::word && grid_keywords.count(token.text) && token.first_on_line)
                fail(token.line, std::to_string(expected) + " values and a '/' terminator",
                     std::to_string(found) + " values, then keyword " + std::string(token.text));
            const RepeatItem item = split_repeat(token.text);
            if (!item.valid) fail(token.line, "a value or N*value with N a positive integer", describe(token));
            if (item.value.empty())
                fail(token.line, "a value (defaults N* are not allowed here)", describe(token));
            if (item.count > expected - found)
                fail(token.line, std::to_string(expected) + " values",
                     "more (at least " + std::to_string(found + item.count) + ")");
            sink(token, item.value, item.count);
            found += item.count;
        }
        if (found != expected) fail(lexer_.line(), std::to_string(expected) + " values", std::to_string(found));
    }

    double finite_value(const Token& token, std::string_view text) {
        const auto value = parse_double(text);
        if (!value) fail(token.line, "a number", describe(token));
        if (!std::isfinite(*value)) fail(token.line, "a finite number", describe(token));
        return *value;
    }

    /// A COORD or ZCORN value: beyond 1e9 model units (a million kilometres) cell volumes and
    /// extents stop being meaningful, and single-precision rendering relative to the model's
    /// centre cannot separate the cells.
    double coordinate_value(const Token& token, std::string_view text) {
        constexpr double max_coordinate = 1e9;
        const double value = finite_value(token, text);
        if (std::abs(value) > max_coordinate) fail(token.line, "a coordinate within +-1e9 model units", describe(token));
        return value;
    }

    long long integer_value(const Token& token, std::string_view text) {
        const auto value = parse_integer(text);
        if (!value) fail(token.line, "an integer", describe(token));
        return *value;
    }

    /// Items up to '/', as raw words (defaults kept as empty strings), for short records.
    std::vector<std::pair<Token, std::string_view>> read_record(std::size_t max_items) {
        std::vector<std::pair<Token, std::string_view>> items;
        for (;;) {
            const Token token = next_token();
            if (token.kind == TokenKind::slash) return items;
            if (token.kind == TokenKind::end) fail(token.line, "a '/' terminator", "end of file");
            const RepeatItem item =
                token.kind == TokenKind::quoted ? RepeatItem{1, token.text, true} : split_repeat(token.text);
            if (!item.valid) fail(token.line, "a value or N*value with N a positive integer", describe(token));
            if (items.size() + item.count > max_items)
                fail(token.line, "at most " + std::to_string(max_items) + " items", "more");
            for (std::size_t n = 0; n < item.count; ++n) items.emplace_back(token, item.value);
        }
    }

    void reserve(std::size_t bytes, const std::string& what) {
        if (bytes > state_.options.memory_limit_bytes - std::min(state_.bytes_reserved, state_.options.memory_limit_bytes))
            fail(keyword_line_, "arrays within the memory limit of " + byte_text(double(state_.options.memory_limit_bytes)),
                 what + " needing " + byte_text(double(bytes)) + " more (" + byte_text(double(state_.bytes_reserved)) +
                     " already held)");
        state_.bytes_reserved += bytes;
    }

    const GridDims& require_dims() {
        if (!state_.dims) fail(keyword_line_, "SPECGRID or DIMENS before " + keyword_, "no grid dimensions yet");
        return *state_.dims;
    }

    CellFilter filter() { return CellFilter(require_dims(), state_.options.block); }

    /// Reads one value per cell of the grid, appending sink(value) for the kept cells.
    template <typename T, typename Parse>
    void read_kept_cells(std::vector<T>& kept, Parse&& parse) {
        const CellFilter cells = filter();
        std::size_t n = 0;
        read_values(require_dims().cell_count(), [&](const Token& token, std::string_view text, std::size_t count) {
            const T value = parse(token, text);
            if (!state_.options.block) kept.insert(kept.end(), count, value);
            else CellFilter::each_kept(n, count, [&](std::size_t c) { return cells.keeps_cell(c); }, [&] { kept.push_back(value); });
            n += count;
        });
    }

    // ---- keywords ----------------------------------------------------------------------

    void read_dims() {
        const auto items = read_record(keyword_ == "SPECGRID" ? 5 : 3);
        if (items.size() < 3) fail(lexer_.line(), "NX NY NZ", std::to_string(items.size()) + " items");
        int n[3] = {0, 0, 0};
        const char* names[3] = {"NX", "NY", "NZ"};
        for (int a = 0; a < 3; ++a) {
            const auto& [token, text] = items[std::size_t(a)];
            const auto value = parse_integer(text);
            if (!value || *value <= 0 || *value > 100'000'000)
                fail(token.line, std::string("a positive integer ") + names[a] + " (at most 1e8)", describe(token));
            n[a] = int(*value);
        }
        if (items.size() >= 4 && !items[3].second.empty() && items[3].second != "1")
            fail(items[3].first.line, "NUMRES 1 (one reservoir)", describe(items[3].first));
        if (items.size() >= 5 && !items[4].second.empty() && items[4].second != "F")
            fail(items[4].first.line, "COORDTYPE F (Cartesian)", describe(items[4].first));
        const GridDims dims{n[0], n[1], n[2]};
        if (state_.dims) {
            if (!(*state_.dims == dims))
                fail(keyword_line_, "the dimensions given before (" + dims_text(*state_.dims) + ")", dims_text(dims));
            return;
        }
        const std::optional<IjkBox>& block = state_.options.block;
        if (block && !(block->i0 >= 0 && block->j0 >= 0 && block->k0 >= 0 && block->i0 <= block->i1 &&
                       block->j0 <= block->j1 && block->k0 <= block->k1 && block->i1 < dims.nx && block->j1 < dims.ny &&
                       block->k1 < dims.nz))
            fail(keyword_line_, "a grid holding the block to read (cells " + std::to_string(block->i0) + " " +
                                    std::to_string(block->j0) + " " + std::to_string(block->k0) + " to " +
                                    std::to_string(block->i1) + " " + std::to_string(block->j1) + " " +
                                    std::to_string(block->k1) + ")",
                 dims_text(dims));
        // Refuse absurd sizes before anything is allocated: the geometry alone needs this much
        // (the kept cells' depths and flags, every pillar).
        const GridDims kept = CellFilter(dims, block).kept_dims();
        const double cells = double(kept.nx) * double(kept.ny) * double(kept.nz);
        const double bytes = double(kept.nx) * kept.ny * (kept.nz + 1.0) * 32.0 + cells + double(dims.nx + 1) * (dims.ny + 1) * 48.0;
        if (bytes > double(state_.options.memory_limit_bytes))
            fail(keyword_line_, "a grid within the memory limit of " + byte_text(double(state_.options.memory_limit_bytes)),
                 dims_text(dims) + " needing at least " + byte_text(bytes));
        state_.dims = dims;
    }

    static std::string dims_text(const GridDims& d) {
        return std::to_string(d.nx) + " x " + std::to_string(d.ny) + " x " + std::to_string(d.nz);
    }

    void forbid_repeat(bool already_read) {
        if (already_read) fail(keyword_line_, "one " + keyword_ + " per grid", "a second " + keyword_);
    }

    void read_coord() {
        const GridDims& dims = require_dims();
        forbid_repeat(!state_.coord.empty());
        reserve(dims.coord_value_count() * sizeof(double), "COORD");
        state_.coord.reserve(dims.coord_value_count());
        read_values(dims.coord_value_count(), [&](const Token& token, std::string_view text, std::size_t count) {
            state_.coord.insert(state_.coord.end(), count, coordinate_value(token, text));
        });
        refuse_pillars_without_area(state_.coord);
        refuse_coinciding_pillars(state_.coord, dims);
    }

    /// Pillars equal to their neighbour along i (all six coordinates) make cells without width.
    /// When most pillars do, the grid is no reservoir but a handful of repeat counts (COORD
    /// 3003003*0 3003003*1 for 1000 x 1000 columns): refused before ZCORN and the properties are
    /// allocated for it. A real grid collapses a few pillars at most (pinched edges).
    void refuse_coinciding_pillars(const std::vector<double>& coord, const GridDims& dims) const {
        if (coord.size() != dims.coord_value_count() || dims.nx < 1) return;
        std::size_t coinciding = 0;
        for (int pj = 0; pj <= dims.ny; ++pj)
            for (int pi = 1; pi <= dims.nx; ++pi) {
                const double* pillar = &coord[6 * dims.pillar_index(pi, pj)];
                coinciding += std::equal(pillar, pillar + 6, pillar - 6);
            }
        const std::size_t pairs = std::size_t(dims.nx) * std::size_t(dims.ny + 1);
        if (2 * coinciding > pairs)
            fail(keyword_line_, "pillars at distinct places (cells with a width)",
                 std::to_string(coinciding) + " of " + std::to_string(pairs) + " pillars equal to their neighbour along i");
    }

    /// Pillars whose ends all share one x or one y span no horizontal area: every cell would have
    /// no area and no volume, and nothing could be drawn. Refused from COORD alone, before ZCORN
    /// and the properties are allocated for cells that cannot exist.
    void refuse_pillars_without_area(const std::vector<double>& coord) const {
        if (coord.size() < 6) return;  // a short COORD is reported at its end
        double x0 = coord[0], x1 = coord[0], y0 = coord[1], y1 = coord[1];
        for (std::size_t n = 0; n + 2 < coord.size(); n += 3) {
            x0 = std::min(x0, coord[n]);
            x1 = std::max(x1, coord[n]);
            y0 = std::min(y0, coord[n + 1]);
            y1 = std::max(y1, coord[n + 1]);
        }
        if (x1 > x0 && y1 > y0) return;
        fail(keyword_line_, "pillars spanning a horizontal area (a non-zero horizontal extent in x and in y)",
             "all " + std::to_string(coord.size() / 6) + " pillars within x [" + number_text(x0) + ", " + number_text(x1) +
                 "], y [" + number_text(y0) + ", " + number_text(y1) + "]");
    }

    void read_zcorn() {
        const GridDims& dims = require_dims();
        forbid_repeat(state_.zcorn.has_value());
        const CellFilter cells = filter();
        const GridDims kept = cells.kept_dims();
        reserve(ZcornStore::compact_bytes(kept), "ZCORN");
        ZcornStore& store = state_.zcorn.emplace(kept);
        // Reserved before the store allocates its full layout (it holds both for a moment).
        const auto expanding = [&] { reserve(ZcornStore::full_bytes(kept), "ZCORN with gaps between layers (full layout)"); };
        std::size_t n = 0;
        read_values(dims.zcorn_value_count(), [&](const Token& token, std::string_view text, std::size_t count) {
            const double value = coordinate_value(token, text);
            if (!state_.options.block) store.push_repeated(value, count, expanding);
            else CellFilter::each_kept(n, count, [&](std::size_t c) { return cells.keeps_corner(c); },
                                       [&] { store.push_repeated(value, 1, expanding); });
            n += count;
        });
    }

    void read_actnum() {
        forbid_repeat(!state_.actnum.empty());
        const std::size_t kept = filter().kept_dims().cell_count();
        reserve(kept, "ACTNUM");
        state_.actnum.reserve(kept);
        read_kept_cells(state_.actnum, [&](const Token& token, std::string_view text) {
            const long long value = integer_value(token, text);
            if (value < 0 || value > 3) fail(token.line, "an ACTNUM flag 0..3", describe(token));
            return std::uint8_t(value != 0);
        });
    }

    void read_mapaxes() {
        std::array<double, 6> axes{};
        std::size_t n = 0;
        read_values(6, [&](const Token& token, std::string_view text, std::size_t count) {
            const double value = finite_value(token, text);
            for (std::size_t c = 0; c < count; ++c) axes[n++] = value;
        });
        state_.metadata.mapaxes = axes;
    }

    /// A short record of words or quoted strings, blanks trimmed; at least one item.
    std::vector<std::string> read_string_items() {
        const auto items = read_record(16);
        if (items.empty()) fail(lexer_.line(), "at least one item", "none");
        std::vector<std::string> strings;
        for (const auto& item : items) {
            const std::string_view s = item.second;
            if (!is_printable_ascii(s)) fail(item.first.line, "a string of printable ASCII characters", describe(item.first));
            const auto b = s.find_first_not_of(' ');
            strings.push_back(b == std::string_view::npos ? std::string()
                                                          : std::string(s.substr(b, s.find_last_not_of(' ') - b + 1)));
        }
        return strings;
    }

    void read_include();

    template <typename T, typename Parse>
    std::vector<T> read_cell_array(Parse&& parse) {
        const std::size_t kept = filter().kept_dims().cell_count();
        reserve(kept * sizeof(T), keyword_);
        std::vector<T> values;
        values.reserve(kept);
        read_kept_cells(values, parse);
        return values;
    }

    void read_known_property() {
        if (is_integer_property(keyword_)) {
            auto values = read_cell_array<std::int32_t>([&](const Token& token, std::string_view text) {
                const long long v = integer_value(token, text);
                if (v < INT32_MIN || v > INT32_MAX) fail(token.line, "a 32-bit integer", describe(token));
                return std::int32_t(v);
            });
            store_int_property(std::move(values));
            return;
        }
        auto values = read_cell_array<float>([&](const Token& token, std::string_view text) {
            // Read as float directly: a shortest float text round-trips exactly only this way.
            const auto v = parse_float(text);
            if (!v) fail(token.line, "a number", describe(token));
            return *v;
        });
        store_float_property(std::move(values));
    }

    void store_float_property(std::vector<float> values) {
        if (dynamic_property_keywords.count(keyword_)) {
            state_.dynamic_properties[keyword_].push_back(std::move(values));
            return;
        }
        if (state_.float_properties.count(keyword_)) warn(keyword_line_, shown_keyword(keyword_) + " given again: the later values are kept");
        state_.float_properties[keyword_] = std::move(values);
    }

    void store_int_property(std::vector<std::int32_t> values) {
        if (state_.int_properties.count(keyword_)) warn(keyword_line_, shown_keyword(keyword_) + " given again: the later values are kept");
        state_.int_properties[keyword_] = std::move(values);
    }

    /// An unknown keyword: kept as a property when it holds one number per cell, else skipped.
    void read_unknown() {
        const Token next = lexer_.peek();
        if (next.kind == TokenKind::end || (looks_like_keyword(next) && next.text != keyword_)) {
            warn(keyword_line_, "unknown keyword " + shown_keyword(keyword_) + " without data skipped");
            return;
        }
        const std::size_t cells = state_.dims ? state_.dims->cell_count() : 0;
        const CellFilter kept_cells(state_.dims ? *state_.dims : GridDims{}, state_.options.block);
        const std::size_t kept = cells > 0 ? kept_cells.kept_dims().cell_count() : 0;
        std::vector<double> values;
        std::size_t count = 0;
        bool numeric = true, reserved = false;
        for (;;) {
            const Token token = next_token();
            if (token.kind == TokenKind::slash) break;
            if (token.kind == TokenKind::end) fail(token.line, "a '/' terminator", "end of file");
            if (token.kind == TokenKind::word && grid_keywords.count(token.text) && token.first_on_line)
                fail(token.line, "a '/' terminator", "keyword " + std::string(token.text));
            const RepeatItem item =
                token.kind == TokenKind::quoted ? RepeatItem{1, token.text, true} : split_repeat(token.text);
            const auto value = token.kind == TokenKind::word && item.valid && !item.value.empty()
                                   ? parse_double(item.value)
                                   : std::nullopt;
            numeric = numeric && value.has_value();
            if (numeric && count + item.count <= cells) {
                if (!reserved) reserve(kept * sizeof(double), keyword_);
                reserved = true;
                CellFilter::each_kept(count, item.count, [&](std::size_t c) { return kept_cells.keeps_cell(c); },
                                      [&] { values.push_back(*value); });
            }
            count += std::min(item.count, std::size_t(1) << 40);
        }
        if (reserved) state_.bytes_reserved -= kept * sizeof(double);  // released on return
        if (numeric && cells > 0 && count == cells) {
            reserve(kept * sizeof(float), keyword_);
            store_float_property(std::vector<float>(values.begin(), values.end()));
            warn(keyword_line_, "unknown keyword " + shown_keyword(keyword_) + " read as a per-cell real property");
            return;
        }
        warn(keyword_line_, "unknown keyword " + shown_keyword(keyword_) + " (" + std::to_string(count) + " items) skipped");
    }

    GrdeclReader::State& state_;
    GrdeclLexer lexer_;
    std::string file_;
    std::filesystem::path base_dir_;
    std::string keyword_;
    int keyword_line_ = 0;
};

/// A file's text counted against the memory limit while it is held (nested INCLUDEs add up).
class HeldText {
public:
    HeldText(GrdeclReader::State& state, std::string text) : state_(state), text_(std::move(text)) {}
    ~HeldText() { state_.bytes_reserved -= std::min(state_.bytes_reserved, text_.size()); }
    HeldText(const HeldText&) = delete;
    HeldText& operator=(const HeldText&) = delete;
    std::string_view text() const { return text_; }

private:
    GrdeclReader::State& state_;
    std::string text_;
};

/// Reads `path` whole after checking its size against what the memory limit leaves; `from` and
/// `from_line` name the INCLUDE that asked for it (empty for a file given directly).
std::string read_whole_file(const std::filesystem::path& path, GrdeclReader::State& state, const std::string& from,
                            int from_line) {
    auto fail = [&](std::string expected, std::string found) -> std::string {
        throw GrdeclError({from.empty() ? io::shown_path(path) : from, from_line, from.empty() ? "" : "INCLUDE",
                           std::move(expected), std::move(found)});
    };
    const std::string readable = "a readable GRDECL file " + io::shown_path(path);
    if (const std::string found = io::input_file_problem(path); !found.empty()) return fail(readable, found);
    std::error_code error;
    const auto size = std::filesystem::file_size(path, error);
    if (error) return fail(readable, error.message());
    const std::size_t limit = state.options.memory_limit_bytes;
    const std::size_t left = limit - std::min(limit, state.bytes_reserved);
    if (size > left)
        return fail("a file within the memory limit of " + byte_text(double(limit)) + " (" +
                        byte_text(double(state.bytes_reserved)) + " already held)",
                    io::shown_path(path) + " of " + byte_text(double(size)));
    state.bytes_reserved += size;
    std::ifstream in(path, std::ios::binary);
    std::string text(size, '\0');
    if (!in.read(text.data(), std::streamsize(size)))
        return fail(readable, "a read error");
    return text;
}

void KeywordParser::read_include() {
    const auto items = read_record(1);
    if (items.size() != 1 || items[0].second.empty()) fail(lexer_.line(), "one file name", "none");
    const int line = items[0].first.line;
    if (!state_.options.allow_include) fail(line, "no INCLUDE (disabled for this input)", quote(items[0].second));
    std::filesystem::path path(std::string(items[0].second));
    if (path.is_relative()) path = base_dir_ / path;
    std::error_code error;
    const auto canonical = std::filesystem::weakly_canonical(path, error);
    const auto& stack = state_.include_stack;
    if (std::find(stack.begin(), stack.end(), canonical) != stack.end()) {
        std::string chain;
        for (const auto& p : stack) chain += p.filename().string() + " -> ";
        fail(line, "an INCLUDE without loops", "a loop " + chain + canonical.filename().string());
    }
    if (int(stack.size()) > state_.options.max_include_depth)
        fail(line, "INCLUDE nesting of at most " + std::to_string(state_.options.max_include_depth), "deeper nesting");
    if (state_.options.before_include) state_.options.before_include(path, file_ + ":" + std::to_string(line));
    const HeldText text(state_, read_whole_file(path, state_, file_, line));
    state_.include_stack.push_back(canonical);
    KeywordParser(state_, text.text(), path.string(), path.parent_path()).run();
    state_.include_stack.pop_back();
}

}  // namespace

namespace {

/// `coord` (the whole grid's pillars) narrowed to the pillars of `block`'s cells.
void narrow_coord(const GridDims& dims, const IjkBox& block, std::vector<double>& coord) {
    std::vector<double> kept;
    kept.reserve(block.dims().coord_value_count());
    for (int pj = block.j0; pj <= block.j1 + 1; ++pj) {
        const auto first = coord.begin() + std::ptrdiff_t(6 * dims.pillar_index(block.i0, pj));
        kept.insert(kept.end(), first, first + std::ptrdiff_t(6 * (block.i1 - block.i0 + 2)));
    }
    coord = std::move(kept);
}

}  // namespace

GrdeclReader::GrdeclReader(GrdeclReadOptions options) : state_(std::make_unique<State>()) {
    state_->options = options;
}

GrdeclReader::~GrdeclReader() = default;

void GrdeclReader::read_file(const std::filesystem::path& path) {
    const HeldText text(*state_, read_whole_file(path, *state_, "", 0));
    std::error_code error;
    state_->include_stack = {std::filesystem::weakly_canonical(path, error)};
    if (state_->first_file.empty()) state_->first_file = path.string();
    KeywordParser(*state_, text.text(), path.string(), path.parent_path()).run();
    state_->include_stack.clear();
}

void GrdeclReader::read_text(std::string_view text, const std::string& name, const std::filesystem::path& base_dir) {
    if (text.size() > state_->options.memory_limit_bytes)
        throw GrdeclError({name, 0, "", "text within the memory limit of " + byte_text(double(state_->options.memory_limit_bytes)),
                           byte_text(double(text.size()))});
    if (state_->first_file.empty()) state_->first_file = name;
    KeywordParser(*state_, text, name, base_dir).run();
}

const std::vector<std::string>& GrdeclReader::warnings() const { return state_->warnings; }

CornerPointGrid GrdeclReader::finish() {
    State& s = *state_;
    auto missing = [&](const char* keyword, const char* expected) {
        throw GrdeclError({s.first_file, 0, keyword, expected, "none in the input"});
    };
    if (!s.dims) missing("SPECGRID", "SPECGRID or DIMENS giving the grid dimensions");
    if (s.coord.empty()) missing("COORD", "COORD with the pillars");
    if (!s.zcorn) missing("ZCORN", "ZCORN with the corner depths");
    if (s.options.block) narrow_coord(*s.dims, *s.options.block, s.coord);
    CornerPointGrid grid(CellFilter(*s.dims, s.options.block).kept_dims(), std::move(s.coord), std::move(*s.zcorn),
                         std::move(s.actnum));
    grid.metadata() = std::move(s.metadata);
    for (auto& [name, values] : s.float_properties) grid.set_property(name, std::move(values));
    for (auto& [name, values] : s.int_properties) grid.set_int_property(name, std::move(values));
    for (auto& [name, steps] : s.dynamic_properties)
        for (auto& values : steps) grid.add_dynamic_step(name, std::move(values));
    auto fresh = std::make_unique<State>();
    fresh->options = s.options;
    fresh->warnings = std::move(s.warnings);  // still readable after finish()
    state_ = std::move(fresh);
    return grid;
}

GridDims read_grdecl_dims(const std::vector<std::filesystem::path>& files, const GrdeclReadOptions& options) {
    GrdeclReadOptions without_block = options;
    without_block.block.reset();
    GrdeclReader reader(without_block);
    reader.state_->stop_at_dims = true;
    for (const auto& file : files) {
        reader.read_file(file);
        if (reader.state_->dims) return *reader.state_->dims;
    }
    return reader.finish().dims();  // throws: no SPECGRID or DIMENS
}

CornerPointGrid load_grdecl(const std::vector<std::filesystem::path>& files, const GrdeclReadOptions& options,
                            std::vector<std::string>* warnings) {
    GrdeclReader reader(options);
    for (const auto& file : files) reader.read_file(file);
    if (warnings) *warnings = reader.warnings();
    return reader.finish();
}

}  // namespace cutaway::grid

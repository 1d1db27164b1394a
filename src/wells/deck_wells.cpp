#include "wells/deck_wells.h"

#include <fnmatch.h>

#include <algorithm>
#include <string>

#include <opm/input/eclipse/Deck/Deck.hpp>
#include <opm/input/eclipse/Deck/DeckItem.hpp>
#include <opm/input/eclipse/Deck/DeckKeyword.hpp>
#include <opm/input/eclipse/Deck/DeckRecord.hpp>
#include <opm/input/eclipse/Parser/ErrorGuard.hpp>
#include <opm/input/eclipse/Parser/InputErrorAction.hpp>
#include <opm/input/eclipse/Parser/ParseContext.hpp>
#include <opm/input/eclipse/Parser/Parser.hpp>
#include <opm/input/eclipse/Parser/ParserKeywords/C.hpp>
#include <opm/input/eclipse/Parser/ParserKeywords/W.hpp>

#include "io/bad_input_error.h"

namespace cutaway::wells {
namespace {

namespace fs = std::filesystem;
namespace keywords = Opm::ParserKeywords;

/// OPM's multi-line messages ("Problem with keyword X / In FILE line N. / reason") as one line.
std::string one_line(std::string text) {
    std::replace(text.begin(), text.end(), '\n', ' ');
    while (!text.empty() && text.back() == ' ') text.pop_back();
    return text;
}

std::string where(const Opm::DeckKeyword& keyword) {
    return keyword.location().filename + ":" + std::to_string(keyword.location().lineno) + ": keyword " + keyword.name();
}

Opm::Deck parse_deck(const fs::path& file) {
    std::error_code error;
    if (!fs::is_regular_file(file, error))
        throw io::BadInputError(file.string() + ": expected a deck file with WELSPECS and COMPDAT, found no such file");
    // Only the well keywords are known to the parser: everything else (grids, tables, arrays) is
    // skipped as an unknown keyword instead of being parsed.
    Opm::Parser parser(false);
    parser.addKeyword<keywords::WELSPECS>();
    parser.addKeyword<keywords::COMPDAT>();
    parser.addKeyword<keywords::WCONPROD>();
    parser.addKeyword<keywords::WCONHIST>();
    parser.addKeyword<keywords::WCONINJE>();
    parser.addKeyword<keywords::WCONINJH>();
    Opm::ParseContext context;
    context.update(Opm::InputError::IGNORE);
    Opm::ErrorGuard errors;
    try {
        Opm::Deck deck = parser.parseFile(file.string(), context, errors);
        errors.clear();
        return deck;
    } catch (const std::exception& e) {
        errors.clear();
        throw io::BadInputError(file.string() + ": expected deck keywords WELSPECS and COMPDAT, found: " + one_line(e.what()));
    }
}

Well* find_well(std::vector<Well>& wells, const std::string& name) {
    const auto found = std::find_if(wells.begin(), wells.end(), [&](const Well& w) { return w.name == name; });
    return found == wells.end() ? nullptr : &*found;
}

void add_welspecs(const Opm::DeckKeyword& keyword, std::vector<Well>& wells) {
    for (const Opm::DeckRecord& record : keyword) {
        const std::string name = record.getItem<keywords::WELSPECS::WELL>().getTrimmedString(0);
        const int i = record.getItem<keywords::WELSPECS::HEAD_I>().get<int>(0) - 1;
        const int j = record.getItem<keywords::WELSPECS::HEAD_J>().get<int>(0) - 1;
        Well* well = find_well(wells, name);
        if (!well) well = &wells.emplace_back(Well{name, WellKind::unknown, "", WellStatus::open, i, j, {}});
        well->head_i = i;  // a later WELSPECS moves the wellhead
        well->head_j = j;
    }
}

/// A COMPDAT I or J: defaulted or 0 means the wellhead's.
int column_or_head(const Opm::DeckItem& item, int head) {
    return item.defaultApplied(0) || item.get<int>(0) == 0 ? head : item.get<int>(0) - 1;
}

void add_connection(Well& well, const WellConnection& connection) {
    for (WellConnection& c : well.connections)
        if (c.i == connection.i && c.j == connection.j && c.k == connection.k) {
            c.open = connection.open;
            return;
        }
    well.connections.push_back(connection);
}

void add_compdat(const Opm::DeckKeyword& keyword, std::vector<Well>& wells) {
    for (const Opm::DeckRecord& record : keyword) {
        const std::string pattern = record.getItem<keywords::COMPDAT::WELL>().getTrimmedString(0);
        const int k1 = record.getItem<keywords::COMPDAT::K1>().get<int>(0);
        const int k2 = record.getItem<keywords::COMPDAT::K2>().get<int>(0);
        if (k1 < 1 || k2 < k1)
            throw io::BadInputError(where(keyword) + ": well " + pattern + ": expected layers 1 <= K1 <= K2, found K1 " +
                                    std::to_string(k1) + ", K2 " + std::to_string(k2));
        const auto& state = record.getItem<keywords::COMPDAT::STATE>();
        const bool open = state.defaultApplied(0) || state.getTrimmedString(0) != "SHUT";
        bool matched = false;
        for (Well& well : wells) {
            if (fnmatch(pattern.c_str(), well.name.c_str(), 0) != 0) continue;
            matched = true;
            const int i = column_or_head(record.getItem<keywords::COMPDAT::I>(), well.head_i);
            const int j = column_or_head(record.getItem<keywords::COMPDAT::J>(), well.head_j);
            for (int k = k1; k <= k2; ++k) add_connection(well, {i, j, k - 1, open});
        }
        if (!matched)
            throw io::BadInputError(where(keyword) + ": expected a well defined by WELSPECS before, found " + pattern);
    }
}

WellStatus status_named(const std::string& text) {
    if (text == "SHUT") return WellStatus::shut;
    if (text == "STOP") return WellStatus::stop;
    if (text == "AUTO") return WellStatus::automatic;
    return WellStatus::open;
}

/// Kind and status of every well matching the record's pattern that no control keyword set yet.
template <class Item>
void add_control(const Opm::DeckRecord& record, WellKind kind, const std::string& phase, std::vector<Well>& wells,
                 std::vector<std::string>& controlled) {
    const std::string pattern = record.getItem(0).getTrimmedString(0);
    const auto& status = record.getItem<Item>();
    for (Well& well : wells) {
        if (fnmatch(pattern.c_str(), well.name.c_str(), 0) != 0) continue;
        if (std::find(controlled.begin(), controlled.end(), well.name) != controlled.end()) continue;
        controlled.push_back(well.name);
        well.kind = kind;
        well.injected_phase = phase;
        well.status = status.defaultApplied(0) ? WellStatus::open : status_named(status.getTrimmedString(0));
    }
}

void add_controls(const Opm::DeckKeyword& keyword, std::vector<Well>& wells, std::vector<std::string>& controlled) {
    for (const Opm::DeckRecord& record : keyword) {
        const std::string& name = keyword.name();
        if (name == "WCONPROD") add_control<keywords::WCONPROD::STATUS>(record, WellKind::producer, "", wells, controlled);
        if (name == "WCONHIST") add_control<keywords::WCONHIST::STATUS>(record, WellKind::producer, "", wells, controlled);
        if (name == "WCONINJE")
            add_control<keywords::WCONINJE::STATUS>(record, WellKind::injector,
                                                    record.getItem<keywords::WCONINJE::TYPE>().getTrimmedString(0), wells,
                                                    controlled);
        if (name == "WCONINJH")
            add_control<keywords::WCONINJH::STATUS>(record, WellKind::injector,
                                                    record.getItem<keywords::WCONINJH::TYPE>().getTrimmedString(0), wells,
                                                    controlled);
    }
}

}  // namespace

std::vector<Well> read_deck_wells(const fs::path& file) {
    const Opm::Deck deck = parse_deck(file);
    std::vector<Well> wells;
    std::vector<std::string> controlled;
    for (std::size_t index = 0; index < deck.size(); ++index) {
        const Opm::DeckKeyword& keyword = deck[index];
        try {
            if (keyword.name() == "WELSPECS") add_welspecs(keyword, wells);
            else if (keyword.name() == "COMPDAT") add_compdat(keyword, wells);
            else add_controls(keyword, wells, controlled);
        } catch (const io::BadInputError&) {
            throw;
        } catch (const std::exception& e) {  // an item OPM could not give (a required one left out)
            throw io::BadInputError(where(keyword) + ": expected every required item, found: " + one_line(e.what()));
        }
    }
    if (wells.empty()) throw io::BadInputError(file.string() + ": expected deck keyword WELSPECS defining wells, found none");
    return wells;
}

}  // namespace cutaway::wells

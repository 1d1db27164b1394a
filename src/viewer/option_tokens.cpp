#include "viewer/option_tokens.h"

#include <stdexcept>

#include "viewer/viewer_state.h"

namespace cutaway::viewer {

unsigned apply_option_tokens(app::RenderOptions& options, const std::vector<std::string>& tokens) {
    app::RenderOptions updated = options;
    CLI::App parser{"viewer script set"};
    app::add_selection_options(parser, updated);
    app::add_frame_options(parser, updated);
    std::vector<std::string> reversed(tokens.rbegin(), tokens.rend());  // CLI11 takes them last first
    try {
        parser.parse(reversed);
    } catch (const CLI::ParseError& error) {
        throw std::invalid_argument(std::string("set: ") + error.what());
    }
    if (!reversed.empty()) throw std::invalid_argument("set: unexpected argument '" + reversed.back() + "'");
    const bool range_given = parser.count("--range") > 0, fraction_given = parser.count("--primary-fraction") > 0;
    if (range_given && fraction_given) throw std::invalid_argument("set: give either --range or --primary-fraction, not both");
    if (parser.count("--property") && !parser.count("--step")) updated.step = -1;  // a new property starts static or at step 0
    if (parser.count("--property") && !range_given && !fraction_given) {  // the old range means nothing now
        updated.range.clear();
        updated.primary_fraction = 0;
    }
    if (range_given) updated.primary_fraction = 0;
    if (fraction_given) updated.range.clear();
    updated.frame_settings();  // throws naming the option for a bad value
    const bool selection = range_given || fraction_given || parser.count("--property") || parser.count("--step") ||
                           parser.count("--ijk-box");
    options = std::move(updated);
    return change_frame | (selection ? change_selection : change_none);
}

}  // namespace cutaway::viewer

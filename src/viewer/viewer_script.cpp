#include "viewer/viewer_script.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <system_error>

#include "io/input_file.h"
#include "io/path_text.h"
#include "volumes/cut_volume_spec.h"

namespace cutaway::viewer {

namespace {

using Args = std::vector<std::string>;

/// What is wrong with one line; the parser adds the location and the expected form.
struct LineProblem {
    std::string what;
};

std::string upper_case(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::toupper(c)); });
    return text;
}

std::string lower_case(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return text;
}

void require_count(const Args& args, std::size_t count) {
    if (args.size() != count)
        throw LineProblem{std::to_string(args.size()) + " argument" + (args.size() == 1 ? "" : "s") + " given"};
}

/// The whole token as a finite number within [lo, hi]; `name` is the argument's name in the usage.
double number_in(const std::string& token, std::string_view name, double lo, double hi) {
    double value = 0;
    const char* end = token.data() + token.size();
    const auto [stop, error] = std::from_chars(token.data(), end, value);
    if ((error != std::errc() && error != std::errc::result_out_of_range) || stop != end)
        throw LineProblem{std::string(name) + " '" + token + "' is not a number"};
    if (error == std::errc::result_out_of_range || !std::isfinite(value)) throw LineProblem{std::string(name) + " '" + token + "' is not finite"};
    if (value < lo || value > hi) throw LineProblem{std::string(name) + " " + token + " is out of range"};
    return value;
}

double finite_number(const std::string& token, std::string_view name) {
    return number_in(token, name, -HUGE_VAL, HUGE_VAL);
}

void check_wait(Args& args) {
    require_count(args, 1);
    long frames = 0;
    const std::string& token = args[0];
    const char* end = token.data() + token.size();
    const auto [stop, error] = std::from_chars(token.data(), end, frames);
    if (error != std::errc() || stop != end) throw LineProblem{"N '" + token + "' is not a whole number"};
    if (frames < 0 || frames > 100000) throw LineProblem{"N " + token + " is out of range"};
}

void check_sleep(Args& args) {
    require_count(args, 1);
    number_in(args[0], "SECONDS", 0, 3600);
}

void check_orbit(Args& args) {
    require_count(args, 2);
    finite_number(args[0], "DAZ");
    finite_number(args[1], "DEL");
}

void check_pan(Args& args) {
    require_count(args, 2);
    number_in(args[0], "DX", -10, 10);
    number_in(args[1], "DY", -10, 10);
}

void check_zoom(Args& args) {
    require_count(args, 1);
    if (number_in(args[0], "FACTOR", 0, 100) == 0) throw LineProblem{"FACTOR 0 is out of range"};
}

void check_camera(Args& args) {
    require_count(args, 3);
    finite_number(args[0], "AZ");
    number_in(args[1], "EL", -89, 89);
    number_in(args[2], "DIST", 0, HUGE_VAL);
}

void check_set(Args& args) {
    if (args.empty()) throw LineProblem{"no option given"};
    if (args[0].rfind("--", 0) != 0) throw LineProblem{"'" + args[0] + "' is not an option"};
}

constexpr std::array<std::string_view, 6> key_names{"F", "H", "R", "SPACE", "F12", "ESCAPE"};

void check_key(Args& args) {
    require_count(args, 1);
    args[0] = upper_case(args[0]);
    if (std::find(key_names.begin(), key_names.end(), args[0]) == key_names.end())
        throw LineProblem{"unknown key '" + args[0] + "'"};
}

void check_on_off(Args& args) {
    require_count(args, 1);
    if (args[0] != "on" && args[0] != "off") throw LineProblem{"'" + args[0] + "' is neither on nor off"};
}

void check_playback(Args& args) {
    require_count(args, 2);
    if (args[0] != "none" && args[0] != "smooth") throw LineProblem{"coherence '" + args[0] + "' is neither none nor smooth"};
    number_in(args[1], "FRAMES_PER_STEP", 1, 1000);
    if (args[1].find_first_not_of("0123456789") != std::string::npos)
        throw LineProblem{"FRAMES_PER_STEP '" + args[1] + "' is not a whole number"};
}

void check_volumes(Args& args) {
    if (args.empty()) throw LineProblem{"expected add SPEC, clear, save FILE or load FILE"};
    const std::string& verb = args[0];
    if (verb == "clear") {
        if (args.size() != 1) throw LineProblem{"clear takes no argument"};
    } else if (verb == "add" || verb == "save" || verb == "load") {
        if (args.size() != 2) throw LineProblem{verb + " takes one argument"};
        if (verb == "add") {
            try {
                volumes::parse_cut_volume_spec(args[1]);
            } catch (const std::invalid_argument& error) {
                throw LineProblem{error.what()};
            }
        }
    } else {
        throw LineProblem{"'" + verb + "' is none of add, clear, save, load"};
    }
}

void check_screenshot(Args& args) { require_count(args, 1); }

void check_quit(Args& args) { require_count(args, 0); }

struct ActionRule {
    std::string_view name;
    std::string_view usage;    ///< the expected form, with the arguments' ranges
    std::string_view meaning;  ///< one line for the help text
    void (*check)(Args& args);  ///< throws LineProblem; may normalise args
};

constexpr std::array<ActionRule, 16> action_rules{{
    {"wait", "wait N (whole number of frames, 0..100000)", "render N frames before the next action", check_wait},
    {"sleep", "sleep SECONDS (0..3600)", "keep drawing for SECONDS of wall clock before the next action", check_sleep},
    {"orbit", "orbit DAZ DEL (degrees)", "add DAZ to the azimuth and DEL to the elevation", check_orbit},
    {"pan", "pan DX DY (image heights, -10..10)", "move the scene right by DX and up by DY", check_pan},
    {"zoom", "zoom FACTOR (0 < FACTOR <= 100)", "multiply the eye distance by FACTOR", check_zoom},
    {"camera", "camera AZ EL DIST (degrees, EL in -89..89, DIST >= 0)",
     "set the orbit pose; DIST 0 frames the whole model", check_camera},
    {"set", "set --OPTION [VALUE]... (options of cutaway render)", "change render options, e.g. set --ssao off",
     check_set},
    {"key", "key NAME (F, H, R, SPACE, F12 or ESCAPE)",
     "press a key: F freeze, H panel, R reset camera, SPACE play, F12 screenshot, ESCAPE quit", check_key},
    {"drag", "drag on|off", "hold or release the mouse button: while held the view is moving (--interaction-fps)",
     check_on_off},
    {"freeze", "freeze on|off", "freeze or release the cut surface", check_on_off},
    {"play", "play on|off", "play or pause the time steps", check_on_off},
    {"playback", "playback none|smooth FRAMES_PER_STEP (1..1000)",
     "how play moves between report steps: coherence (as cutaway animate's) and frames from one step to the next",
     check_playback},
    {"ui", "ui on|off", "show or hide the panel", check_on_off},
    {"volumes", "volumes add SPEC | clear | save FILE | load FILE",
     "edit the cut volumes as the panel does (SPEC as --cut-volume's; FILE as --cut-volumes')", check_volumes},
    {"screenshot", "screenshot FILE", "save the next frame as a PNG", check_screenshot},
    {"quit", "quit (no arguments)", "close the viewer", check_quit},
}};

const ActionRule* find_rule(const std::string& name) {
    const auto rule = std::find_if(action_rules.begin(), action_rules.end(),
                                   [&](const ActionRule& r) { return r.name == name; });
    return rule == action_rules.end() ? nullptr : &*rule;
}

std::string joined_action_names() {
    std::string names;
    for (const ActionRule& rule : action_rules) names += (names.empty() ? "" : ", ") + std::string(rule.name);
    return names;
}

/// The line's tokens, without its comment.
std::vector<std::string> line_tokens(const std::string& line) {
    std::istringstream stream(line.substr(0, line.find('#')));
    std::vector<std::string> tokens;
    for (std::string token; stream >> token;) tokens.push_back(token);
    return tokens;
}

}  // namespace

ViewerScript parse_viewer_script_text(const std::string& text, const std::string& path_for_messages) {
    ViewerScript script;
    script.path = path_for_messages;
    std::istringstream lines(text);
    int line_number = 0;
    for (std::string line; std::getline(lines, line);) {
        ++line_number;
        std::vector<std::string> tokens = line_tokens(line);
        if (tokens.empty()) continue;
        const std::string location = path_for_messages + ":" + std::to_string(line_number) + ": ";
        ScriptStep step{line_number, lower_case(tokens[0]), Args(tokens.begin() + 1, tokens.end())};
        const ActionRule* rule = find_rule(step.action);
        if (!rule)
            throw std::invalid_argument(location + "unknown action '" + tokens[0] + "'; expected one of " +
                                        joined_action_names());
        try {
            rule->check(step.args);
        } catch (const LineProblem& problem) {
            throw std::invalid_argument(location + problem.what + "; expected " + std::string(rule->usage));
        }
        script.steps.push_back(std::move(step));
    }
    return script;
}

ViewerScript parse_viewer_script(const std::filesystem::path& path) {
    const std::string name = io::shown_path(path);
    // Checked before opening: a FIFO's open would wait for a writer that may never come.
    if (const std::string found = io::input_file_problem(path); !found.empty())
        throw std::invalid_argument(name + ": expected a readable script file, found " + found);
    std::error_code error;
    const std::uintmax_t bytes = std::filesystem::file_size(path, error);
    std::ifstream file(path, std::ios::binary);
    if (error || !file) throw std::invalid_argument(name + ": cannot open");
    if (bytes > max_script_bytes)
        throw std::invalid_argument(name + ": " + std::to_string(bytes) + " bytes; expected a script of at most 1 MiB");
    std::ostringstream text;
    text << file.rdbuf();
    return parse_viewer_script_text(text.str(), name);
}

std::string describe(const ViewerScript& script, const ScriptStep& step) {
    std::string text = script.path + ":" + std::to_string(step.line) + ": " + step.action;
    for (const std::string& arg : step.args) text += " " + arg;
    return text;
}

std::vector<std::string> script_actions() {
    std::vector<std::string> names;
    for (const ActionRule& rule : action_rules) names.emplace_back(rule.name);
    return names;
}

std::string script_actions_help() {
    std::string help = "Script actions (one per line, # starts a comment):\n";
    for (const ActionRule& rule : action_rules)
        help += "  " + std::string(rule.usage) + "\n      " + std::string(rule.meaning) + "\n";
    return help;
}

}  // namespace cutaway::viewer

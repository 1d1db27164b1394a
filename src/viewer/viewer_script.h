#pragma once
// `cutaway view --script FILE`: viewer actions and camera moves, one per line, checked in full
// before the first frame so a typo fails at once rather than minutes into a recording.
//
// Syntax: one action per line, tokens separated by whitespace, `#` starts a comment anywhere on a
// line, blank lines are ignored. Files over 1 MiB are refused. script_actions_help() lists the actions.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace cutaway::viewer {

struct ScriptStep {
    int line = 0;                    ///< 1-based line number in the file
    std::string action;              ///< lower case: one of script_actions()
    std::vector<std::string> args;   ///< tokens after the action, as written (key names upper-cased)
};

struct ViewerScript {
    std::string path;
    std::vector<ScriptStep> steps;  ///< in file order
};

/// Largest script file accepted (bytes).
inline constexpr std::uintmax_t max_script_bytes = 1u << 20;

/// Reads and checks a script. Throws std::invalid_argument "PATH: cannot open", "PATH: N bytes; expected
/// at most 1 MiB", or "PATH:LINE: <what is wrong>; expected <what>" for an unknown action, a wrong
/// argument count, a non-number or non-finite number, or an out-of-range value.
ViewerScript parse_viewer_script(const std::filesystem::path& path);

/// parse_viewer_script on text in memory; `path_for_messages` names it in errors and in the result.
ViewerScript parse_viewer_script_text(const std::string& text, const std::string& path_for_messages);

/// "PATH:LINE: action arg..." for logs and run-time errors.
std::string describe(const ViewerScript& script, const ScriptStep& step);

/// The action names, in the order script_actions_help() lists them.
std::vector<std::string> script_actions();

/// Help text listing every action with its arguments, one per line (for --help and error messages).
std::string script_actions_help();

}  // namespace cutaway::viewer

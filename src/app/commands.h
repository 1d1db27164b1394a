#pragma once
// Each `cutaway` subcommand registers itself on the CLI11 app and returns the action to run.
#include <functional>

#include <CLI/CLI.hpp>

namespace cutaway::app {

/// Runs the parsed subcommand; returns the process exit code.
using CommandAction = std::function<int()>;

CommandAction add_inspect_command(CLI::App& app);
CommandAction add_generate_command(CLI::App& app);
CommandAction add_render_command(CLI::App& app);
CommandAction add_animate_command(CLI::App& app);
CommandAction add_volume_command(CLI::App& app);
CommandAction add_generate_seismic_command(CLI::App& app);
CommandAction add_view_command(CLI::App& app);

}  // namespace cutaway::app

// `cutaway view MODEL [options]`: the interactive viewer (src/viewer/).
#include "app/commands.h"
#include "app_core/model_source.h"
#include "app_core/option_checks.h"
#include "viewer/viewer_app.h"
#include "viewer/viewer_script.h"

namespace cutaway::app {
namespace {

/// Refuses, before a window opens, an output naming the model, the script or another output: the
/// --screenshot and --stats files, and every file a script's `screenshot FILE` writes (a script
/// may write one file several times: only its inputs are protected from it).
void refuse_view_overwrites(const viewer::ViewerOptions& options) {
    std::vector<io::NamedFile> inputs = model_input_files(options.render.model);
    inputs.push_back({"--script", options.script});
    refuse_overwrites(inputs, {{"--screenshot", options.screenshot}, {"--stats", options.stats}});
    if (options.script.empty()) return;
    const viewer::ViewerScript script = viewer::parse_viewer_script(options.script);
    for (const viewer::ScriptStep& step : script.steps)
        if (step.action == "screenshot")
            refuse_overwrites(inputs, {{describe(script, step), step.args.at(0)}});
}

}  // namespace

CommandAction add_view_command(CLI::App& app) {
    auto options = std::make_shared<viewer::ViewerOptions>();
    CLI::App* command = app.add_subcommand("view", "Explore a cutaway in a window (GLFW + Dear ImGui); scriptable for tests");
    viewer::add_viewer_options(*command, *options);
    return [options] {
        refuse_view_overwrites(*options);
        return viewer::ViewerApp(*options).run();
    };
}

}  // namespace cutaway::app

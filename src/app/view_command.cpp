// `cutaway view MODEL [options]`: the interactive viewer (src/viewer/).
#include "app/commands.h"
#include "app/option_checks.h"
#include "viewer/viewer_app.h"

namespace cutaway::app {

CommandAction add_view_command(CLI::App& app) {
    auto options = std::make_shared<viewer::ViewerOptions>();
    CLI::App* command = app.add_subcommand("view", "Explore a cutaway in a window (GLFW + Dear ImGui); scriptable for tests");
    viewer::add_viewer_options(*command, *options);
    return [options] {
        // Before a window opens: an output naming the model or another output would overwrite it.
        std::vector<std::pair<std::string, std::string>> files;
        for (const std::string& model : options->render.model) files.emplace_back("the model", model);
        files.insert(files.end(), {{"--screenshot", options->screenshot}, {"--stats", options->stats}});
        refuse_shared_outputs(files);
        return viewer::ViewerApp(*options).run();
    };
}

}  // namespace cutaway::app

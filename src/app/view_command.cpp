// `cutaway view MODEL [options]`: the interactive viewer (src/viewer/).
#include "app/commands.h"
#include "viewer/viewer_app.h"

namespace cutaway::app {

CommandAction add_view_command(CLI::App& app) {
    auto options = std::make_shared<viewer::ViewerOptions>();
    CLI::App* command = app.add_subcommand("view", "Explore a cutaway in a window (GLFW + Dear ImGui); scriptable for tests");
    viewer::add_viewer_options(*command, *options);
    return [options] { return viewer::ViewerApp(*options).run(); };
}

}  // namespace cutaway::app

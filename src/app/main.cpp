// `cutaway`: one program, one subcommand per job (see ../shared/DESIGN.md for the contract).
#include <exception>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "app/commands.h"
#include "app_core/exit_status.h"
#include "app_core/heap_policy.h"
#include "app/mpi_launch.h"
#include "io/interrupt_cleanup.h"

int main(int argc, char** argv) {
    cutaway::app::keep_freed_heap_memory();
    // Ctrl-C or kill removes the temporary files of outputs not yet committed (exit 130 or 143).
    const cutaway::io::InterruptCleanup interrupt_cleanup;
    CLI::App app{"cutaway: corner-point reservoir grids, cutaway rendering and seismic ray casting benchmarks"};
    app.require_subcommand(1);
    // Refused command lines read like every other refusal, on one line: "cutaway: --option:
    // expected ..., found ... (cutaway render --help lists the options)".
    app.failure_message([](const CLI::App* top, const CLI::Error& error) {
        const std::vector<CLI::App*> chosen = top->get_subcommands();
        const std::string help = chosen.empty() ? "cutaway --help lists the subcommands"
                                                : "cutaway " + chosen.front()->get_name() + " --help lists the options";
        return "cutaway: " + std::string(error.what()) + " (" + help + ")\n";
    });
    // One line per subcommand: its registration returns the action run when it is chosen.
    const cutaway::app::CommandAction inspect = cutaway::app::add_inspect_command(app);
    const cutaway::app::CommandAction generate = cutaway::app::add_generate_command(app);
    const cutaway::app::CommandAction render = cutaway::app::add_render_command(app);
    const cutaway::app::CommandAction animate = cutaway::app::add_animate_command(app);
    const cutaway::app::CommandAction volume = cutaway::app::add_volume_command(app);
    const cutaway::app::CommandAction generate_seismic = cutaway::app::add_generate_seismic_command(app);
    const cutaway::app::CommandAction view = cutaway::app::add_view_command(app);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        // CLI11 prints "--option: expected ..., found ..."; every refused command line is bad
        // input (exit 2) whatever CLI11's own code; --help stays 0. Under mpirun rank 0 alone
        // prints it (every rank parses the same command line).
        std::ostringstream silenced;
        const bool quiet = cutaway::app::mpi_rank_from_launcher() > 0;
        return (quiet ? app.exit(error, silenced, silenced) : app.exit(error)) == 0 ? cutaway::app::exit_success
                                                                                   : cutaway::app::exit_bad_input;
    }
    try {
        if (app.got_subcommand("inspect")) return inspect();
        if (app.got_subcommand("generate")) return generate();
        if (app.got_subcommand("render")) return render();
        if (app.got_subcommand("animate")) return animate();
        if (app.got_subcommand("volume")) return volume();
        if (app.got_subcommand("generate-seismic")) return generate_seismic();
        if (app.got_subcommand("view")) return view();
    } catch (...) {
        const cutaway::app::ExitStatus status = cutaway::app::exit_status_of(std::current_exception());
        std::cerr << "cutaway: " << status.message << '\n';
        return status.code;
    }
    return cutaway::app::exit_failure;
}

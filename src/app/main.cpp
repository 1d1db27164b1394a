// `cutaway`: one program, one subcommand per job (see ../shared/DESIGN.md for the contract).
#include <exception>
#include <iostream>
#include <new>
#include <sstream>

#include "app/commands.h"
#include "app/heap_policy.h"
#include "app/mpi_launch.h"
#include "eclipse/eclipse_error.h"
#include "gl/gl_error.h"
#include "grid/grdecl_error.h"
#include "io/output_error.h"
#include "volume/volume_error.h"

int main(int argc, char** argv) {
    cutaway::app::keep_freed_heap_memory();
    CLI::App app{"cutaway: corner-point reservoir grids, cutaway rendering and seismic ray casting benchmarks"};
    app.require_subcommand(1);
    // Refused command lines read like every other refusal: "cutaway: --option: expected ..., found ...".
    app.failure_message([](const CLI::App*, const CLI::Error& error) {
        return "cutaway: " + std::string(error.what()) + "\n(cutaway SUBCOMMAND --help lists the options)\n";
    });
    // One line per subcommand: its registration returns the action run when it is chosen.
    const cutaway::app::CommandAction inspect = cutaway::app::add_inspect_command(app);
    const cutaway::app::CommandAction generate = cutaway::app::add_generate_command(app);
    const cutaway::app::CommandAction render = cutaway::app::add_render_command(app);
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
        return (quiet ? app.exit(error, silenced, silenced) : app.exit(error)) == 0 ? 0 : 2;
    }
    try {
        if (app.got_subcommand("inspect")) return inspect();
        if (app.got_subcommand("generate")) return generate();
        if (app.got_subcommand("render")) return render();
        if (app.got_subcommand("volume")) return volume();
        if (app.got_subcommand("generate-seismic")) return generate_seismic();
        if (app.got_subcommand("view")) return view();
    } catch (const cutaway::grid::GrdeclError& error) {
        std::cerr << "cutaway: " << error.what() << '\n';
        return 2;
    } catch (const cutaway::eclipse::EclipseError& error) {
        std::cerr << "cutaway: " << error.what() << '\n';
        return 2;
    } catch (const cutaway::volume::VolumeError& error) {
        std::cerr << "cutaway: " << error.what() << '\n';
        return 2;
    } catch (const cutaway::io::OutputError& error) {
        std::cerr << "cutaway: " << error.what() << '\n';
        return 2;
    } catch (const cutaway::gl::GlError& error) {
        std::cerr << "cutaway: OpenGL: " << error.what() << '\n';
        return 4;
    } catch (const std::invalid_argument& error) {
        std::cerr << "cutaway: " << error.what() << '\n';
        return 2;
    } catch (const std::bad_alloc&) {
        std::cerr << "cutaway: out of memory (lower the input size or raise --memory-limit-gb)\n";
        return 3;
    } catch (const std::exception& error) {
        std::cerr << "cutaway: " << error.what() << '\n';
        return 1;
    }
    return 1;
}

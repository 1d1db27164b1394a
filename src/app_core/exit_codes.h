#pragma once
// The exit codes of `cutaway` (README "Exit codes"), shared by main() and the ranks under mpirun.
namespace cutaway::app {

constexpr int exit_success = 0;
constexpr int exit_failure = 1;          ///< an internal error (a bug to report)
constexpr int exit_bad_input = 2;        ///< bad input, a refused option or an output that cannot be written
constexpr int exit_out_of_memory = 3;    ///< an allocation failed although --memory-limit-gb admitted the run
constexpr int exit_gl_failure = 4;       ///< OpenGL could not start or failed
constexpr int exit_interrupted_base = 128;  ///< + the signal: 130 for SIGINT, 143 for SIGTERM

/// What an allocation failure means: the run fit --memory-limit-gb, so the machine (or a ulimit,
/// or other processes) gave less than that limit.
inline constexpr const char* out_of_memory_message =
    "out of memory: this machine (or a ulimit) gave less memory than --memory-limit-gb admits; set --memory-limit-gb "
    "to the memory actually free so the run is refused before it starts, or use a smaller input";

}  // namespace cutaway::app

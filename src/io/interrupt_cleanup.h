#pragma once
// Temporary output files removed when the user interrupts a run (SIGINT: Ctrl-C; SIGTERM: kill,
// or mpirun ending its ranks), so that no `.NAME.partial-XXXXXX` file outlives the command. The
// process then exits with 128 + the signal's number (130, 143), as a shell reports it.
//
// A signal handler receives no context pointer, so the files it removes must sit in a table it
// can reach without one: a fixed array of slots (no allocation, no lock) and two counters, the only
// global state of this module. Every slot's state is one lock-free atomic, so the handler (on
// whichever thread the signal lands) claims a slot before reading its path and never reads one
// being rewritten; a file is created and registered as one step for the handler (DeferredInterrupts),
// so a signal cannot fall between the two and leave the file unknown to it.
#include <csignal>
#include <cstddef>

namespace cutaway::io {

/// Installs the SIGINT and SIGTERM handlers for its lifetime (main() holds one) and restores the
/// previous ones when destroyed. Without one, registered files are simply not removed on a signal.
class InterruptCleanup {
public:
    InterruptCleanup();
    ~InterruptCleanup();
    InterruptCleanup(const InterruptCleanup&) = delete;
    InterruptCleanup& operator=(const InterruptCleanup&) = delete;

private:
    struct sigaction previous_interrupt_ {};
    struct sigaction previous_terminate_ {};
};

/// While one lives, SIGINT and SIGTERM wait; the last one to end handles a signal that came
/// meanwhile (removes the files and exits). For steps a signal must not cut in two: creating and
/// registering a file, renaming the outputs of one run onto their targets.
class DeferredInterrupts {
public:
    DeferredInterrupts();
    ~DeferredInterrupts();
    DeferredInterrupts(const DeferredInterrupts&) = delete;
    DeferredInterrupts& operator=(const DeferredInterrupts&) = delete;
};

/// The most temporary files registered at once (a run stages a handful of outputs).
constexpr std::size_t max_interrupt_files = 64;

/// mkstemp(`name_template`) and the new file registered for removal on a signal, as one step
/// (DeferredInterrupts). Returns the open descriptor and sets `slot`; or -1 with errno set when the file cannot
/// be made (ENAMETOOLONG for a path of PATH_MAX or more), or interrupt_table_full.
int create_interrupt_file(char* name_template, int& slot);
/// create_interrupt_file's result when every slot is taken (the file was not kept).
constexpr int interrupt_table_full = -2;
/// Forgets the file of `slot` (from create_interrupt_file; -1 is ignored): it was renamed or removed.
void release_interrupt_file(int slot);

}  // namespace cutaway::io

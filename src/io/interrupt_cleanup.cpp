#include "io/interrupt_cleanup.h"

#include <cerrno>
#include <climits>
#include <csignal>
#include <cstring>
#include <unistd.h>

#include <atomic>

namespace cutaway::io {
namespace {

enum SlotState : int { free_slot = 0, writing = 1, ready = 2, claimed = 3 };

/// One registered file. `state` goes free -> writing -> ready (registered) -> free (released), or
/// ready -> claimed when the handler removes the file: only a ready slot is read by the handler,
/// and only a free one is rewritten.
struct InterruptSlot {
    std::atomic<int> state{free_slot};
    char path[PATH_MAX] = {};
};
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler needs lock-free atomics");

// The handler's state (see the header: a handler has no other way to reach it): the table, how
// many DeferredInterrupts live, and a signal deferred meanwhile.
InterruptSlot interrupt_slots[max_interrupt_files];
std::atomic<int> deferring_steps{0};
std::atomic<int> deferred_signal{0};

extern "C" void remove_files_and_exit(int signal_number) {
    for (InterruptSlot& slot : interrupt_slots) {
        int expected = ready;
        if (slot.state.compare_exchange_strong(expected, claimed)) ::unlink(slot.path);
    }
    ::_exit(128 + signal_number);
}

extern "C" void on_interrupt(int signal_number) {
    deferred_signal.store(signal_number);
    // A step that must not be cut in two is running: it ends the process when it is done.
    if (deferring_steps.load() > 0) return;
    remove_files_and_exit(signal_number);
}

/// Puts `path` in a free slot; -1 when every slot is taken.
int register_path(const char* path) {
    for (std::size_t n = 0; n < max_interrupt_files; ++n) {
        InterruptSlot& slot = interrupt_slots[n];
        int expected = free_slot;
        if (!slot.state.compare_exchange_strong(expected, writing)) continue;
        std::memcpy(slot.path, path, std::strlen(path) + 1);
        slot.state.store(ready);
        return int(n);
    }
    return -1;
}

}  // namespace

InterruptCleanup::InterruptCleanup() {
    struct sigaction action {};
    action.sa_handler = on_interrupt;
    action.sa_flags = SA_RESTART;  // a deferred signal returns into the interrupted call
    sigemptyset(&action.sa_mask);
    sigaddset(&action.sa_mask, SIGINT);  // one handler runs at a time
    sigaddset(&action.sa_mask, SIGTERM);
    ::sigaction(SIGINT, &action, &previous_interrupt_);
    ::sigaction(SIGTERM, &action, &previous_terminate_);
}

InterruptCleanup::~InterruptCleanup() {
    ::sigaction(SIGINT, &previous_interrupt_, nullptr);
    ::sigaction(SIGTERM, &previous_terminate_, nullptr);
}

DeferredInterrupts::DeferredInterrupts() { deferring_steps.fetch_add(1); }

DeferredInterrupts::~DeferredInterrupts() {
    if (deferring_steps.fetch_sub(1) == 1)
        if (const int signal_number = deferred_signal.load(); signal_number != 0) remove_files_and_exit(signal_number);
}

int create_interrupt_file(char* name_template, int& slot) {
    slot = -1;
    if (std::strlen(name_template) >= PATH_MAX) {
        errno = ENAMETOOLONG;
        return -1;
    }
    const DeferredInterrupts creating;  // the file must not exist unregistered when a signal is handled
    const int fd = ::mkstemp(name_template);
    if (fd < 0) return -1;
    slot = register_path(name_template);
    if (slot >= 0) return fd;
    ::close(fd);
    ::unlink(name_template);
    return interrupt_table_full;
}

void release_interrupt_file(int slot) {
    if (slot < 0) return;
    int expected = ready;
    // A claimed slot belongs to the handler, which ends the process: leave it as it is.
    interrupt_slots[slot].state.compare_exchange_strong(expected, free_slot);
}

}  // namespace cutaway::io

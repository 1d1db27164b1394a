#include "app/interrupt_guard.h"

#include <pthread.h>

#include <cstring>
#include <ctime>

namespace cutaway::app {

Interrupted::Interrupted(int signal_number)
    : std::runtime_error(std::string("interrupted by ") + (::strsignal(signal_number) ? ::strsignal(signal_number) : "a signal")),
      signal_number_(signal_number) {}

InterruptGuard::InterruptGuard() {
    sigemptyset(&held_);
    for (int signal_number : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&held_, signal_number);
    pthread_sigmask(SIG_BLOCK, &held_, &previous_);
}

InterruptGuard::~InterruptGuard() {
    const timespec no_wait{0, 0};
    while (::sigtimedwait(&held_, nullptr, &no_wait) > 0) {
    }
    pthread_sigmask(SIG_SETMASK, &previous_, nullptr);
}

void InterruptGuard::check() const {
    sigset_t pending;
    sigemptyset(&pending);
    ::sigpending(&pending);
    for (int signal_number : {SIGINT, SIGTERM, SIGHUP})
        if (sigismember(&held_, signal_number) && sigismember(&pending, signal_number)) throw Interrupted(signal_number);
}

}  // namespace cutaway::app

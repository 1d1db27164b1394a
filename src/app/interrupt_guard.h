#pragma once
// While a long command runs, SIGINT, SIGTERM and SIGHUP are held pending instead of ending the
// process at once: the command looks between frames, stops, removes its partial outputs (and any
// child it spawned) and exits with 128 + the signal. Signal masks are per thread and inherited:
// the guard is made before any thread starts (the GL driver's, OpenMP's, an encoder's), so
// none of them takes the signal instead.
#include <stdexcept>
#include <string>

#include <signal.h>

namespace cutaway::app {

/// Thrown between frames when a held signal is pending.
class Interrupted : public std::runtime_error {
public:
    explicit Interrupted(int signal_number);
    int signal_number() const { return signal_number_; }

private:
    int signal_number_;
};

class InterruptGuard {
public:
    InterruptGuard();
    /// Takes the held signals that are still pending (they were answered by Interrupted) and
    /// restores the thread's signal mask.
    ~InterruptGuard();
    InterruptGuard(const InterruptGuard&) = delete;
    InterruptGuard& operator=(const InterruptGuard&) = delete;

    /// Throws Interrupted when one of the held signals is pending.
    void check() const;

private:
    sigset_t held_{};
    sigset_t previous_{};
};

}  // namespace cutaway::app

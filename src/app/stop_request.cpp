#include "rccm/app/stop_request.hpp"

#include "rccm/base/child_process.hpp"
#include "rccm/base/errors.hpp"
#include "rccm/la/parallel.hpp"

#include <atomic>
#include <csignal>
#include <cstdlib>
#include <string>
#include <unistd.h>

namespace rccm {

namespace {
volatile std::sig_atomic_t requested = 0;
volatile std::sig_atomic_t at_once = 0;  // a run's set-up: nothing written yet
// Under mpirun: the stop all processes agreed on at the last share_stop_request, the one they
// act on (a signal that reaches a process after it waits for the next step's agreement). Not
// this process's own first signal: a signal after it must still stop it cleanly, not at once.
volatile std::sig_atomic_t shared = 0;

std::atomic_flag exiting = ATOMIC_FLAG_INIT;  // lock-free: a signal handler may use it

/// "rccm: stopped by signal N during set-up; nothing was written" in one write(2), which a
/// signal handler may call (one call: the message is never interleaved with another).
void say_stopped_in_setup(int signal) {
  const char head[] = "\nrccm: stopped by signal ", tail[] = " during set-up; nothing was written\n";
  char message[sizeof head + 3 + sizeof tail];
  std::size_t n = 0;
  for (const char c : head)
    if (c != '\0') message[n++] = c;
  for (int d = 100; d > 0; d /= 10)
    if (signal >= d || d == 1) message[n++] = static_cast<char>('0' + signal / d % 10);
  for (const char c : tail)
    if (c != '\0') message[n++] = c;
  if (::write(STDERR_FILENO, message, n) < 0) return;
}

// The first signal asks the run to stop at its next accepted step; a second one (Ctrl-C
// again) exits at once: the CSV lines and renamed files are complete, a file being written
// under a temporary name is left behind as such. During a run's set-up the first one does.
// A signal sent both to the process and to its group (timeout(1) does) can run this handler
// in two threads at once: the first to exit does, the other waits for the exit.
extern "C" void on_signal(int signal) {
  if (requested || at_once) {
    if (exiting.test_and_set())
      for (;;) ::pause();
    if (at_once) say_stopped_in_setup(signal);
    std::_Exit(128 + signal);
  }
  requested = signal;
  signal_children(signal);  // gmsh meshing for a sweep stops too, not after minutes
}
}  // namespace

void exit_at_once_until_writing() { at_once = 1; }

void writing_started() { at_once = 0; }

void install_stop_handlers() {
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
}

int stop_signal() { return requested ? requested : shared; }

void request_stop(int signal) { requested = signal; }

void share_stop_request() {
  if (parallel::size() == 1) return;
  shared = parallel::largest(stop_signal());
}

void throw_if_stop_requested(int step, double t) {
  if (const int signal = parallel::size() > 1 ? int(shared) : stop_signal())
    throw Interrupted("stopped by signal " + std::to_string(signal) + " after step " + std::to_string(step) +
                          " at t = " + std::to_string(t) + " s",
                      signal);
}

}  // namespace rccm

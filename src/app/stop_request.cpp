#include "rccm/app/stop_request.hpp"

#include "rccm/base/errors.hpp"

#include <csignal>
#include <cstdlib>
#include <string>
#include <unistd.h>
#include <utility>

namespace rccm {

namespace {
volatile std::sig_atomic_t requested = 0;
volatile std::sig_atomic_t at_once = 0;  // a run's set-up: nothing written yet

/// "rccm: stopped by signal N during set-up; nothing was written" with write(2), which a
/// signal handler may call.
void say_stopped_in_setup(int signal) {
  const char head[] = "\nrccm: stopped by signal ", tail[] = " during set-up; nothing was written\n";
  char digits[4];
  int n = 0;
  for (int d = 100; d > 0; d /= 10)
    if (signal >= d || d == 1) digits[n++] = static_cast<char>('0' + signal / d % 10);
  for (const auto& [text, size] : {std::pair<const char*, std::size_t>{head, sizeof head - 1}, {digits, std::size_t(n)},
                                   {tail, sizeof tail - 1}})
    if (::write(STDERR_FILENO, text, size) < 0) return;
}

// The first signal asks the run to stop at its next accepted step; a second one (Ctrl-C
// again) exits at once: the CSV lines and renamed files are complete, a file being written
// under a temporary name is left behind as such. During a run's set-up the first one does.
extern "C" void on_signal(int signal) {
  if (at_once) say_stopped_in_setup(signal);
  if (requested || at_once) std::_Exit(128 + signal);
  requested = signal;
}
}  // namespace

void exit_at_once_until_writing() { at_once = 1; }

void writing_started() { at_once = 0; }

void install_stop_handlers() {
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
}

int stop_signal() { return requested; }

void request_stop(int signal) { requested = signal; }

void throw_if_stop_requested(int step, double t) {
  if (const int signal = stop_signal())
    throw Interrupted("stopped by signal " + std::to_string(signal) + " after step " + std::to_string(step) +
                          " at t = " + std::to_string(t) + " s",
                      signal);
}

}  // namespace rccm

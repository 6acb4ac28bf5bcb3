#include "rccm/app/stop_request.hpp"

#include "rccm/base/errors.hpp"

#include <csignal>
#include <cstdlib>
#include <string>

namespace rccm {

namespace {
volatile std::sig_atomic_t requested = 0;
// The first signal asks the run to stop at its next accepted step; a second one (Ctrl-C
// again) exits at once: the CSV lines and renamed files are complete, a file being written
// under a temporary name is left behind as such.
extern "C" void on_signal(int signal) {
  if (requested) std::_Exit(128 + signal);
  requested = signal;
}
}  // namespace

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

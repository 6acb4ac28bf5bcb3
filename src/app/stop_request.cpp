#include "rccm/app/stop_request.hpp"

#include "rccm/base/errors.hpp"

#include <csignal>
#include <string>

namespace rccm {

namespace {
volatile std::sig_atomic_t requested = 0;
extern "C" void on_signal(int signal) { requested = signal; }
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

#include "rccm/stop_request.hpp"

#include <csignal>

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

}  // namespace rccm

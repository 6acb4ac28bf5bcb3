// SIGINT and SIGTERM ask a run to stop: the handler only records the request, and the run
// stops at its next accepted step with complete files (throw_if_stop_requested). A second
// signal exits at once.
#pragma once

namespace rccm {

/// Installs the handlers of SIGINT and SIGTERM (rccm run and sweep).
void install_stop_handlers();

/// The signal that asked to stop, or 0.
int stop_signal();

/// Asks to stop as the signal `signal` would (tests); 0 withdraws the request.
void request_stop(int signal);

/// Throws Interrupted naming the step and time when a stop was asked.
void throw_if_stop_requested(int step, double t);

}  // namespace rccm

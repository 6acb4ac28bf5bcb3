// SIGINT and SIGTERM ask a run to stop: the handler only records the request, and the run
// stops at its next accepted step with complete files (throw_if_stop_requested). A second
// signal exits at once, and so does a first one during a run's set-up, before it writes.
#pragma once

namespace rccm {

/// Installs the handlers of SIGINT and SIGTERM (rccm run and sweep).
void install_stop_handlers();

/// From now until writing_started(), a signal ends the process at once with a message on
/// stderr: a run's set-up (mesh, factorizations, W0) writes nothing and can take minutes, so
/// there is nothing to stop cleanly (rccm run; a sweep's cases write while others set up).
void exit_at_once_until_writing();

/// The run is about to write its files: a signal now stops it at its next accepted step.
void writing_started();

/// The signal that asked to stop, or 0.
int stop_signal();

/// Asks to stop as the signal `signal` would (tests); 0 withdraws the request.
void request_stop(int signal);

/// Under mpirun with several processes: a stop asked of any process is asked of all of them
/// (each gets its signal at its own moment), so that all stop at the same accepted step; every
/// process calls it at every accepted step. In one process, nothing.
void share_stop_request();

/// Throws Interrupted naming the step and time when a stop was asked; under mpirun, when one
/// was asked by the last share_stop_request (a signal since then waits for the next).
void throw_if_stop_requested(int step, double t);

}  // namespace rccm

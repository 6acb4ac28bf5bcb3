// Error types of rccm and the always-on check macro.
//
// Exit statuses of the rccm executable follow the error type:
//   InputError  -> 2  (bad config, bad command line: nothing was run or written)
//   SolveError  -> 3  (a run that could not go on: it says where and what to change)
//   Interrupted -> 128 + signal (SIGINT 130, SIGTERM 143: stopped cleanly at an accepted step)
#pragma once

#include <stdexcept>
#include <string>

namespace rccm {

/// Bad input: the message names the file, line and setting (see Config).
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Bad input that is too large for this machine: a factorization whose size is known only
/// once its ordering is (the message says how much it needs and has); the caller names the
/// setting.
struct MemoryShortfall : InputError {
  using InputError::InputError;
};

/// A solve that failed: the message names time, step, node and a suggestion. `node`: the
/// contact node it concerns, for a caller that knows where that node is (Model::locate).
struct SolveError : std::runtime_error {
  explicit SolveError(const std::string& what, int node = -1) : std::runtime_error(what), node(node) {}
  int node;
};

/// A result file that could not be written (disk full, directory removed): the run stops.
struct WriteError : SolveError {
  using SolveError::SolveError;
};

/// A run stopped at an accepted step because SIGINT or SIGTERM asked it to (StopRequest).
struct Interrupted : std::runtime_error {
  Interrupted(const std::string& what, int signal) : std::runtime_error(what), signal(signal) {}
  int signal;
};

/// A broken internal invariant (a bug in rccm, not in the input).
struct InternalError : std::logic_error {
  using std::logic_error::logic_error;
};

}  // namespace rccm

/// Always-on check of an internal invariant; appends file:line (as MFEM_VERIFY).
#define RCCM_VERIFY(cond, msg)                                                       \
  do {                                                                               \
    if (!(cond))                                                                     \
      throw ::rccm::InternalError(std::string(msg) + " [" __FILE__ ":" +             \
                                  std::to_string(__LINE__) + "]");                   \
  } while (0)

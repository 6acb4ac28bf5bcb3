// Work that may crash the process, run in a child process instead: a library that aborts
// (gmsh throws some input errors from its OpenMP threads, where nothing can catch them) or
// that the kernel kills for its memory ends the child, and the caller says what happened.
#pragma once

#include <functional>
#include <string>

namespace rccm {

/// How a child ended: `finished` with what its work returned in `bytes`, or not (then
/// `bytes` may be cut short), ended by `signal` (0: it exited without an answer).
struct ChildOutcome {
  bool finished = false;
  std::string bytes;
  int signal = 0;
};

/// Runs `work` in a forked child, in a thread of its own (OpenMP's thread pool of the
/// calling thread does not survive a fork: the child's first parallel region would wait for
/// it forever), with its stdout and stderr closed, and returns what it returned. `work`
/// must catch its exceptions; one it lets out ends the child without an answer. Throws
/// std::runtime_error when no process can be started.
ChildOutcome run_in_child(const std::function<std::string()>& work);

}  // namespace rccm

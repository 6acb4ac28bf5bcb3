// Work that may crash the process, run by another program instead: a library that aborts
// (gmsh throws some input errors from its OpenMP threads, where nothing can catch them) or
// that the kernel kills for its memory ends that process, and the caller says what happened.
// A program, not a fork of the caller: nothing of the caller's threads (OpenMP's pool,
// OpenBLAS's, a sweep's cases) is copied into it, and the caller need not load its libraries.
#pragma once

#include <string>
#include <vector>

namespace rccm {

/// How a child ended: `finished` (exit status 0) with what it wrote to its file descriptor 3
/// in `bytes`, or not (then `bytes` may be cut short): ended by `signal`, or (signal 0)
/// exited with `status`.
struct ChildOutcome {
  bool finished = false;
  std::string bytes;
  int signal = 0;
  int status = 0;
};

/// Runs `program` with `args` (argv[1] on), its stdin, stdout and stderr on /dev/null, its
/// answer read from a pipe on its file descriptor 3 and no other descriptor of the caller
/// open, and waits for it. Throws
/// std::runtime_error naming the program when it cannot be started.
ChildOutcome run_program(const std::string& program, const std::vector<std::string>& args);

/// Sends `signal` to the programs run_program is waiting for. Async-signal-safe: rccm's stop
/// handler calls it, so that a stop asked of rccm alone (kill -INT PID, a scheduler's
/// SIGTERM) ends gmsh's meshing too instead of waiting for it (Ctrl-C reaches the whole
/// process group anyway).
void signal_children(int signal);

/// In the child: ends it (SIGKILL) when the caller ends, and makes it the first process the
/// kernel stops when the memory runs out, not the caller. `caller` is the caller's process id
/// as it passed it; false when the caller has already ended.
bool follow_caller(long caller);

}  // namespace rccm

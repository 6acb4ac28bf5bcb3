// A program run as a child process (base/child_process, how rccm runs rccm-gmsh): what it
// writes to its descriptor 3 arrives whole, however long; a crash, an exit without an
// answer and a program that cannot start are told apart; its stdout is not the answer; SIGINT
// ends it even when the caller ignores it; only the answer's descriptor is open in it.
#include "rccm/base/child_process.hpp"

#include <catch2/catch.hpp>

#include <csignal>
#include <fcntl.h>
#include <stdexcept>
#include <unistd.h>

using namespace rccm;

TEST_CASE("child process: its answer arrives whole and a crash or an exit without an answer is reported", "[child_process]") {
  // 3 MiB (many times a pipe's buffer) of a known pattern, and noise on stdout and stderr.
  const ChildOutcome whole = run_program("/bin/sh", {"-c", "echo noise; echo noise >&2; yes 0123456789abcde | head -c 3145728 >&3"});
  std::string pattern;
  while (pattern.size() < (3u << 20)) pattern += "0123456789abcde\n";
  pattern.resize(3u << 20);
  CHECK(whole.finished);
  CHECK(whole.signal == 0);
  CHECK(whole.bytes == pattern);

  const ChildOutcome aborted = run_program("/bin/sh", {"-c", "printf part >&3; kill -ABRT $$"});
  CHECK_FALSE(aborted.finished);
  CHECK(aborted.signal == SIGABRT);
  CHECK(aborted.bytes == "part");

  const ChildOutcome failed = run_program("/bin/sh", {"-c", "exit 7"});
  CHECK_FALSE(failed.finished);
  CHECK(failed.signal == 0);
  CHECK(failed.status == 7);

  CHECK_THROWS_WITH(run_program("/nonexistent/rccm-gmsh", {}), Catch::Contains("cannot start /nonexistent/rccm-gmsh"));
}

TEST_CASE("child process: Ctrl-C ends it even where the caller ignores SIGINT (a shell's background job)", "[child_process]") {
  const auto previous = std::signal(SIGINT, SIG_IGN);
  const ChildOutcome out = run_program("/bin/sh", {"-c", "kill -INT $$; printf survived >&3"});
  std::signal(SIGINT, previous);
  CHECK_FALSE(out.finished);
  CHECK(out.signal == SIGINT);
  CHECK(out.bytes.empty());
}

TEST_CASE("child process: a descriptor the caller left open without close-on-exec is not open in it", "[child_process]") {
  const int null = ::open("/dev/null", O_RDONLY);  // as a pipe from rccm's own parent, or MPI's socket
  const int fd = ::fcntl(null, F_DUPFD, 10);     // above the answer's 3 (F_DUPFD: no close-on-exec)
  ::close(null);
  REQUIRE(fd >= 10);
  const std::string path = "/proc/self/fd/" + std::to_string(fd);
  const ChildOutcome out = run_program("/bin/sh", {"-c", "if [ -e " + path + " ]; then printf open >&3; else printf closed >&3; fi"});
  ::close(fd);
  CHECK(out.finished);
  CHECK(out.bytes == "closed");
}

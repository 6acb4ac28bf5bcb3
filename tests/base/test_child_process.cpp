// Work run in a child process (base/child_process): what it returns arrives whole, however
// long; a crash or an escaped exception ends the child, not the caller, and is told apart;
// OpenMP still runs in the child after the caller's thread has used it.
#include "rccm/base/child_process.hpp"

#include <catch2/catch.hpp>

#include <csignal>
#include <cstdlib>
#include <omp.h>
#include <stdexcept>
#include <unistd.h>

using namespace rccm;

TEST_CASE("child process: its answer arrives whole and a crash or an escaped exception is reported", "[child_process]") {
  std::string big(3 << 20, '\0');  // many times a pipe's buffer
  for (std::size_t k = 0; k < big.size(); ++k) big[k] = static_cast<char>(k * 7919 % 251);
  const ChildOutcome whole = run_in_child([&] { return big; });
  CHECK(whole.finished);
  CHECK(whole.signal == 0);
  CHECK(whole.bytes == big);

  const ChildOutcome aborted = run_in_child([]() -> std::string { std::abort(); });
  CHECK_FALSE(aborted.finished);
  CHECK(aborted.signal == SIGABRT);

  const ChildOutcome thrown = run_in_child([]() -> std::string { throw std::runtime_error("escaped"); });
  CHECK_FALSE(thrown.finished);
  CHECK(thrown.signal == 0);
}

TEST_CASE("child process: OpenMP runs in the child after the caller's thread used it", "[child_process]") {
  int in_caller = 0;
#pragma omp parallel num_threads(2) reduction(+ : in_caller)
  in_caller += 1;
  REQUIRE(in_caller == 2);
  const ChildOutcome out = run_in_child([] {
    ::alarm(30);  // a child waiting for the caller's lost OpenMP threads ends by SIGALRM
    int in_child = 0;
#pragma omp parallel num_threads(2) reduction(+ : in_child)
    in_child += 1;
    return std::to_string(in_child);
  });
  CHECK(out.signal == 0);
  CHECK(out.finished);
  CHECK(out.bytes == "2");
}

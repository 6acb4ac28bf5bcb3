// The compressed sweeps' threads chosen by their timings (la/thread_choice.hpp), on made-up
// timings: the faster count wins, a shared machine (one thread faster) is noticed at the first
// probe, its end at a later one, and the occasional stalled sweep counts by its time.
#include "rccm/la/thread_choice.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <functional>
#include <vector>

using namespace rccm;

namespace {

/// `n` sweeps timed by `seconds(sweep, threads)`: the threads each was made with.
std::vector<int> sweeps(ThreadChoice& choice, int n, int first, const std::function<double(int, int)>& seconds) {
  std::vector<int> used;
  for (int k = first; k < first + n; ++k) {
    const int threads = choice.threads();
    choice.record(threads, seconds(k, threads));
    used.push_back(threads);
  }
  return used;
}

/// How many of the sweeps were made with `threads` threads.
long count(const std::vector<int>& used, int threads) { return std::count(used.begin(), used.end(), threads); }

}  // namespace

TEST_CASE("Thread choice: with one thread there is nothing to choose and nothing is probed", "[thread-choice]") {
  ThreadChoice choice(1);
  const std::vector<int> used = sweeps(choice, 500, 0, [](int, int) { return 1.0; });
  CHECK(count(used, 1) == 500);
  CHECK(choice.chosen() == 1);
}

TEST_CASE("Thread choice: alone on the machine two threads stay chosen and one is only probed", "[thread-choice]") {
  ThreadChoice choice(2, 100, 3);
  // Two threads 1.6 times as fast (the 2116-node peel's sweeps alone).
  const std::vector<int> used = sweeps(choice, 500, 0, [](int, int threads) { return threads == 2 ? 1.0 : 1.6; });
  // A probe of 3 sweeps after the first 3, then after 100 at the chosen count, then after 200
  // (each probe that confirms the choice doubles the sweeps to the next).
  CHECK(used[0] == 2);
  CHECK(used[3] == 1);
  CHECK(used[6] == 2);
  CHECK(used[105] == 2);
  CHECK(used[106] == 1);
  CHECK(used[109] == 2);
  CHECK(used[308] == 2);
  CHECK(used[309] == 1);
  CHECK(count(used, 1) == 3 * 3);
  CHECK(used.back() == 2);
  CHECK(choice.chosen() == 2);
}

TEST_CASE("Thread choice: a shared machine is noticed at the first probe and its end at a later one",
          "[thread-choice]") {
  ThreadChoice choice(2, 100, 3);
  // Sweeps 0-299: another process holds a core, the two threads wait for each other (4 times
  // as slow as one thread, as the 625-node peel beside a busy loop); from sweep 300 alone.
  const auto seconds = [](int sweep, int threads) {
    if (sweep < 300) return threads == 2 ? 4.0 : 1.0;
    return threads == 2 ? 1.0 : 1.6;
  };
  const std::vector<int> shared = sweeps(choice, 300, 0, seconds);
  CHECK(shared[3] == 1);  // the probe: one thread
  CHECK(shared[6] == 1);  // ... chosen
  CHECK(count(shared, 2) <= 3 + 3 * 3);  // the first sweeps, then 3-sweep probes of two
  const std::vector<int> alone = sweeps(choice, 300, 300, seconds);
  // Two threads again at the next probe, within 100 + 3 sweeps.
  int back = -1;
  for (int k = 0; k < int(alone.size()) && back < 0; ++k)
    if (k >= 3 && alone[k] == 2 && alone[k - 1] == 2 && alone[k - 2] == 2 && alone[k - 3] == 2) back = k;
  CHECK(back >= 0);
  CHECK(back <= 100 + 3 + 3);
  CHECK(alone.back() == 2);
}

TEST_CASE("Thread choice: stalls count by their time, one interrupted probe sweep does not flip the choice",
          "[thread-choice]") {
  // Two threads: 1 per sweep but every other sweep stalled (3): a mean of 2 against one
  // thread's 1.6, though the median sweep is faster in two threads.
  ThreadChoice stalled(2, 100, 5);
  const std::vector<int> used =
      sweeps(stalled, 400, 0, [](int sweep, int threads) { return threads == 1 ? 1.6 : (sweep % 2 == 0 ? 3.0 : 1.0); });
  CHECK(used[5] == 1);
  CHECK(stalled.chosen() == 1);
  CHECK(count(used, 2) <= 5 + 5 * 3);
  // Two threads faster (1 against 1.6), one sweep of the first probe at one thread interrupted:
  // two threads stay chosen, and the next probe finds the same.
  ThreadChoice alone(2, 100, 5);
  const std::vector<int> used_alone =
      sweeps(alone, 400, 0, [](int sweep, int threads) { return threads == 2 ? 1.0 : (sweep == 6 ? 20.0 : 1.6); });
  CHECK(used_alone[5] == 1);
  CHECK(alone.chosen() == 2);
  CHECK(count(used_alone, 1) == 5 * 3);  // probes after 5, 100 and 200 chosen sweeps
}

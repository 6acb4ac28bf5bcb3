// How many threads share the compressed W0's products in a contact solve, chosen by the
// sweeps' measured speed. Threads split a sweep's large block products (la/hodlr.cpp) and wait
// for each other at each block: where other work shares the cores and the scheduler parks one
// thread, a block now and then waits a time slice for it (the 625-node corner peel beside one
// busy process: 9.3 ms per contact solve in two threads, 2.92 ms in one; alone 2.4-2.9 ms in
// either; the 2116-node peel alone is 1.5 times as fast in two). So the sweeps are timed: after
// the first `probe` sweeps, then after `interval` sweeps at the chosen count, `probe` sweeps
// at the other one; the count with the smaller mean time per sweep is chosen from then on
// (means, not medians: the occasional stalled block is the whole cost). A probe that confirms
// the choice doubles the sweeps to the next (up to max_interval_factor times `interval`); a
// change brings them back to `interval`. The products' slices do not depend on the count
// (blas_threads::slices()): the choice moves no bit of a result.
#pragma once

namespace rccm {

class ThreadChoice {
 public:
  /// `most`: the threads there are (blas_threads::most_products()); at 1 there is nothing to
  /// choose and no sweep is probed.
  explicit ThreadChoice(int most, int interval = 100, int probe = 10);

  /// The count chosen (for the solve's other products).
  int chosen() const { return chosen_; }
  /// The threads for the next sweep: the chosen count, or the other one during a probe.
  int threads() const { return probing_ > 0 ? other() : chosen_; }
  /// The sweep made with `threads` threads took `seconds`.
  void record(int threads, double seconds);

 private:
  int other() const { return chosen_ == 1 ? most_ : 1; }

  int most_, interval_, probe_;
  int chosen_;
  static constexpr int max_interval_factor = 16;
  int due_;              // chosen sweeps between two probes, now
  int probing_ = 0;      // sweeps of the current probe still to make
  bool probed_ = false;  // a probe was made (the first comes after `probe` sweeps)
  // Since the last probe: the chosen count's sweeps and their time; the probe's time.
  int chosen_count_ = 0;
  double chosen_seconds_ = 0, probe_seconds_ = 0;
};

}  // namespace rccm

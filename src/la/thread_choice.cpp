#include "rccm/la/thread_choice.hpp"

#include <algorithm>

namespace rccm {

ThreadChoice::ThreadChoice(int most, int interval, int probe)
    : most_(std::max(1, most)), interval_(interval), probe_(probe), chosen_(most_), due_(probe) {}

void ThreadChoice::record(int threads, double seconds) {
  if (most_ == 1) return;
  if (probing_ > 0 && threads == other()) {
    probe_seconds_ += seconds;
    if (--probing_ > 0) return;
    // The probe's mean time per sweep against the chosen count's since the last probe.
    if (probe_seconds_ / probe_ < chosen_seconds_ / chosen_count_) {
      chosen_ = other();
      due_ = interval_;
    } else if (probed_) {
      due_ = std::min(2 * due_, max_interval_factor * interval_);  // confirmed: probe half as often
    } else {
      due_ = interval_;
    }
    chosen_count_ = 0, chosen_seconds_ = probe_seconds_ = 0;
    probed_ = true;
    return;
  }
  if (threads != chosen_) return;  // a sweep made before the choice moved
  chosen_seconds_ += seconds;
  // The first probe after `probe` sweeps, then after due_ (`interval`, doubled while confirmed).
  if (++chosen_count_ >= due_) probing_ = probe_;
}

}  // namespace rccm

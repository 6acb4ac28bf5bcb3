#include "rccm/base/time_function.hpp"

#include <algorithm>

namespace rccm {

double TimeFunction::operator()(double time) const {
  if (t.empty()) return 0.0;
  if (time <= t.front()) return v.front();
  if (time >= t.back()) return v.back();
  const auto k = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), time) - t.begin());
  const double s = (time - t[k - 1]) / (t[k] - t[k - 1]);
  return v[k - 1] + s * (v[k] - v[k - 1]);
}

}  // namespace rccm

// A load amplitude in time: piecewise linear through points (t_k, v_k), constant outside.
#pragma once

#include <vector>

namespace rccm {

struct TimeFunction {
  std::vector<double> t, v;
  double operator()(double time) const;
};

}  // namespace rccm

// The single-node solution of the beta ODE under a prescribed opening u_n = v t (docs/MODEL.md s3):
//   alpha beta' = -(C v^2 t^2 beta - w)^+,  beta(0) = beta0.
// Inactive until t0 = sqrt(w / (C v^2 beta0)); after it the ODE is linear and stays active,
// and the integrating factor exp(k t^3), k = C v^2 / (3 alpha), gives
//   beta(t) = beta0 exp(-k (t^3 - t0^3)) + (w / alpha) int_t0^t exp(-k (t^3 - s^3)) ds.
// The integral is taken by adaptive Simpson to 1e-13 (t - t0).
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>

namespace rccm::test {

inline double adaptive_simpson(const std::function<double(double)>& f, double a, double b, double fa, double fm,
                               double fb, double whole, double tol, int depth) {
  const double m = 0.5 * (a + b), lm = 0.5 * (a + m), rm = 0.5 * (m + b);
  const double flm = f(lm), frm = f(rm);
  const double left = (m - a) / 6 * (fa + 4 * flm + fm), right = (b - m) / 6 * (fm + 4 * frm + fb);
  if (depth <= 0 || std::abs(left + right - whole) <= 15 * tol) return left + right + (left + right - whole) / 15;
  return adaptive_simpson(f, a, m, fa, flm, fm, left, tol / 2, depth - 1) +
         adaptive_simpson(f, m, b, fm, frm, fb, right, tol / 2, depth - 1);
}

inline double exact_beta(double t, double C, double v, double w, double alpha, double beta0) {
  const double t0 = std::sqrt(w / (C * v * v * beta0));
  if (t <= t0) return beta0;
  const double k = C * v * v / (3 * alpha);
  // The integrand lies in (0, 1] with one boundary layer at s = t: adaptive Simpson resolves it.
  const auto g = [&](double s) { return std::exp(-k * (t * t * t - s * s * s)); };
  const double m = 0.5 * (t0 + t), ga = g(t0), gm = g(m), gb = g(t);
  const double whole = (t - t0) / 6 * (ga + 4 * gm + gb);
  const double I = adaptive_simpson(g, t0, t, ga, gm, gb, whole, 1e-13 * (t - t0), 40);
  return beta0 * std::exp(-k * (t * t * t - t0 * t0 * t0)) + w / alpha * I;
}

/// The rate-independent limit alpha -> 0: beta = min(beta0, w / (C v^2 t^2)).
inline double rate_independent_beta(double t, double C, double v, double w, double beta0) {
  return t > 0 ? std::min(beta0, w / (C * v * v * t * t)) : beta0;
}

}  // namespace rccm::test

// Anderson acceleration of a fixed-point iteration y -> G(y) (Anderson 1965; Walker and Ni
// 2011; docs/solvers/anderson.md). After each sweep took y_k to G(y_k), the
// next iterate is the combination of the last few G's whose residuals f = G(y) - y combine to
// the least norm:
//   gamma = argmin |f_k - dF gamma|,   y_{k+1} = G(y_k) - dG gamma
// (dF, dG: differences of consecutive f and G). On a fixed status pattern the Gauss-Seidel
// sweep is affine in y and this is GMRES in disguise; where pairs change status the
// extrapolation is a secant guess that the next sweep's projections correct. Each difference
// is a secant of G between two points it was evaluated at, however the second was reached
// (an exact step in between included): the history stays valid.
//
// u = W0 y + q0 is affine in y: the same combination of the sweeps' u's gives the u of the
// combined y, without a product with W0.
#pragma once

#include <Eigen/Core>
#include <Eigen/QR>

namespace rccm {

class AndersonMixing {
 public:
  /// depth: the differences kept (0: no acceleration).
  explicit AndersonMixing(int depth) : depth_(depth) {
    // A rank-revealing QR: nearly parallel differences (a stagnating sweep) are dropped
    // rather than amplified.
    qr_.setThreshold(1e-10);
  }

  /// A new fixed-point iteration: the history forgotten (its memory kept), `depth` differences.
  void restart(int depth) {
    depth_ = depth;
    count_ = next_ = 0;
    has_previous_ = false;
  }

  /// A sweep took y_in to (y, u = W0 y + q0): replaces (y, u) by the extrapolated iterate.
  /// Returns the combination's weight sum |gamma_k| (0: no extrapolation): the mixed u
  /// carries the round-off of the sweeps' u's times about this much (a nearly singular
  /// least-squares problem gives large weights).
  double mix(const Eigen::VectorXd& y_in, Eigen::VectorXd& y, Eigen::VectorXd& u);

 private:
  int depth_;
  int count_ = 0, next_ = 0;  // columns held, and the one to overwrite next
  bool has_previous_ = false;
  Eigen::VectorXd f_, f_previous_, G_previous_, u_previous_;
  Eigen::MatrixXd dF_, dG_, dU_;  // m x depth, circular
  // The least-squares problem's factorization and solution (kept: their memory is reused).
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr_;
  Eigen::VectorXd gamma_;
};

}  // namespace rccm

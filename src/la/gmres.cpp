#include "rccm/la/gmres.hpp"

#include <Eigen/Dense>

#include <cmath>

namespace rccm {

GmresResult gmres(const LinearMap& A, const LinearMap& M, const Eigen::VectorXd& b, double tolerance,
                  int max_iterations) {
  const Eigen::Index n = b.size(), k_max = max_iterations;
  GmresResult out;
  out.x = Eigen::VectorXd::Zero(n);
  const double beta = b.norm();
  if (beta == 0 || k_max < 1) return out;
  Eigen::MatrixXd V(n, k_max + 1), Z(n, k_max), H = Eigen::MatrixXd::Zero(k_max + 1, k_max);
  Eigen::VectorXd g = Eigen::VectorXd::Zero(k_max + 1), cs(k_max), sn(k_max);
  g[0] = beta;
  V.col(0) = b / beta;
  Eigen::Index k = 0;
  while (k < k_max) {
    // Arnoldi with modified Gram-Schmidt on A M.
    Z.col(k) = M(V.col(k));
    Eigen::VectorXd w = A(Z.col(k));
    for (Eigen::Index i = 0; i <= k; ++i) {
      H(i, k) = V.col(i).dot(w);
      w -= H(i, k) * V.col(i);
    }
    const double h_next = w.norm();
    // Givens rotations keep H upper triangular; g holds the rotated right-hand side.
    for (Eigen::Index i = 0; i < k; ++i) {
      const double upper = cs[i] * H(i, k) + sn[i] * H(i + 1, k);
      H(i + 1, k) = -sn[i] * H(i, k) + cs[i] * H(i + 1, k);
      H(i, k) = upper;
    }
    const double r = std::hypot(H(k, k), h_next);
    if (r == 0) break;  // A M v_k = 0: singular
    cs[k] = H(k, k) / r, sn[k] = h_next / r;
    H(k, k) = r;
    g[k + 1] = -sn[k] * g[k];
    g[k] *= cs[k];
    ++k;
    if (std::abs(g[k]) <= tolerance * beta || h_next == 0) break;  // converged, or the exact solution
    V.col(k) = w / h_next;
  }
  out.iterations = static_cast<int>(k);
  out.residual = std::abs(g[k]);
  if (k == 0) return out;  // A M v_0 = 0 (Eigen's solves are undefined on 0 columns)
  out.coefficients = H.topLeftCorner(k, k).triangularView<Eigen::Upper>().solve(g.head(k));
  out.x = Z.leftCols(k) * out.coefficients;
  return out;
}

}  // namespace rccm

// GMRES with right preconditioning (Saad, Iterative Methods for Sparse Linear Systems, 2nd ed.,
// alg. 9.5) for A x = b with x = M z, A and M given as products: the exact step's solver
// (ActiveSetSystem), where M is the inverse of an earlier matrix and A M is close to I.
#pragma once

#include <Eigen/Core>

#include <functional>

namespace rccm {

using LinearMap = std::function<Eigen::VectorXd(const Eigen::VectorXd&)>;

struct GmresResult {
  Eigen::VectorXd x;             // sum_j coefficients[j] M v_j
  Eigen::VectorXd coefficients;  // one per vector M v_j that A was applied to, in order
  double residual = 0;           // |b - A x| as the iteration estimates it
  int iterations = 0;
};

/// Iterates until the residual estimate falls to `tolerance |b|` or after `max_iterations`
/// (no restart). Calls A once per iteration, on M v_j, and M once per iteration.
GmresResult gmres(const LinearMap& A, const LinearMap& M, const Eigen::VectorXd& b, double tolerance,
                  int max_iterations);

}  // namespace rccm

// The semi-smooth Newton contact solver at fixed beta (docs/solvers/newton.md): Newton's
// method on the Alart-Curnier function F(y) = 0 of the condensed problem (docs/MODEL.md s4),
// unknown y = Rbar + E u (so that u = W0 y + q0 is exact), with a generalized Jacobian of F,
// an Armijo line search on the merit 1/2 |F|^2, and projected Gauss-Seidel sweeps when the
// Newton direction fails (Alart and Curnier 1991; Christensen, Klarbring, Pang and Stromberg
// 1998; Acary, Bremond and Huber 2018).
//
// `iterations` counts Newton steps (a step whose direction fails included) and fallback
// sweeps, `exact_solves` the linear solves with the Jacobian (rejected directions included);
// the solve stops on the bipotential solver's scaled natural-map residual (solver.tolerance),
// so that the two agree to it. Needs a dense or compressed W0.
//
// In 2D F is piecewise affine and a Newton step solves the linear problem of the pairs'
// cases, the exact step's system (active_set.hpp), which keeps its factorization from one
// solve to the next; in 3D the Jacobian J = A + C W0 (A, C block diagonal, with the curvature
// of the friction disk) is applied pair by pair after a product with W0, never formed, in GMRES
// preconditioned with the factorization of an earlier J, kept from step to step and solve to
// solve; J is factorized afresh only where GMRES does not reach the direction's accuracy in a
// few iterations: formed (3 m^2 products) and by its LU (2/3 m^3) on a dense W0, mixed from
// W0's compression and factorized compressed (m r^2 log^2 m) on a compressed one.
#pragma once

#include "rccm/contact/active_set.hpp"
#include "rccm/contact/contact_solver.hpp"

#include <Eigen/LU>

#include <optional>

namespace rccm {

class NewtonSolver final : public ContactSolver {
 public:
  explicit NewtonSolver(const SolverParams& params) : params_(params) {}

  std::string failure_advice() const override;
  void forget_W0() override {
    active_set_.forget();
    kept_jacobian_.reset();
  }
  /// 3D: the Jacobians factorized so far (a cold solve's first step, and where GMRES
  /// preconditioned by the kept factorization fell short or took more than a few iterations).
  int jacobian_factorizations() const { return kept_jacobian_.factorizations; }

  /// The 3D steps' preconditioner, the factorization of the last Jacobian factorized (a cache:
  /// results do not depend on it beyond the direction's accuracy): its LU where W0 is dense,
  /// where W0 is compressed J mixed from W0's compression (J = A + C W0 row by row, HODLR) and
  /// factorized compressed; and how many were factorized.
  struct KeptJacobian {
    std::optional<Eigen::PartialPivLU<Eigen::MatrixXd>> lu;
    std::optional<HodlrMatrix> mixed;
    std::optional<HodlrSolver> hodlr;
    int factorizations = 0;

    /// Whether it is a factorization of m rows.
    bool serves(Eigen::Index m) const { return lu ? lu->rows() == m : hodlr && mixed->size() == m; }
    /// Its inverse times v.
    Eigen::VectorXd solve(const Eigen::VectorXd& v) const { return lu ? Eigen::VectorXd(lu->solve(v)) : Eigen::VectorXd(hodlr->solve(v)); }
    /// J formed densely, factorized by its LU.
    void factorize(const Eigen::MatrixXd& J);
    /// J = Cy + Cw W0 mixed from W0's compression (Cw, Cy: the pairs' blocks side by side).
    void factorize(const HodlrMatrix& W0, const Eigen::MatrixXd& Cw, const Eigen::MatrixXd& Cy);
    void reset();
  };

 private:
  ContactSolution solve_loaded(const ContactProblem& pb, const Eigen::VectorXd& Rbar_start,
                               const Eigen::VectorXd& u_start) override;
  template <int dim>
  class Iteration;
  template <int dim>
  ContactSolution solve_in(const ContactProblem& pb, const Eigen::VectorXd& Rbar_start, const Eigen::VectorXd& u_start);
  SolverParams params_;
  // The 2D Newton steps' system and its factorization, reused while the cases repeat (a
  // cache: results do not depend on it beyond the tolerance).
  ActiveSetSystem<2> active_set_;
  KeptJacobian kept_jacobian_;
};

}  // namespace rccm

// The classical RCCM contact algorithm at fixed beta (docs/solvers/rccm.md), the one of
// Raous, Cangemi and Cocou (1999) in GYPTIS90 that the paper's Tables 1-2 compare with:
// Coulomb friction by a fixed point on the sliding threshold, each step a Tresca problem
// (threshold s_i = mubar_i max(Rbar_n,i, 0) of the previous one) solved by Gauss-Seidel with
// projection and over-relaxation (PSOR) on the interface displacements, with the stiffness
// condensed on the interface and the adhesive springs beta^2 C on its diagonal. No exact
// active-set step: it is the reference the bipotential solver is measured against.
//
// `iterations` counts PSOR sweeps over all pairs, summed over the Tresca problems of the
// solve (the paper's "contact iterations"); it stops on the bipotential solver's criterion.
#pragma once

#include "rccm/contact/contact_solver.hpp"

namespace rccm {

class RccmSolver final : public ContactSolver {
 public:
  explicit RccmSolver(const SolverParams& params) : params_(params) {}

  std::string failure_advice() const override;
  void forget_W0() override { W0_.resize(0, 0); }

 private:
  ContactSolution solve_loaded(const ContactProblem& pb, const Eigen::VectorXd& Rbar_start,
                               const Eigen::VectorXd& u_start) override;
  template <int dim>
  class Iteration;
  template <int dim>
  ContactSolution solve_in(const ContactProblem& pb, const Eigen::VectorXd& Rbar_start,
                           const Eigen::VectorXd& u_start);
  /// The interface stiffness Kc = W0^-1 (with the springs Dref), computed once per W0.
  const Eigen::MatrixXd& stiffness(const ContactProblem& pb);

  SolverParams params_;
  // A cache: the W0 of the last solve, its inverse and that inverse's norm.
  Eigen::MatrixXd W0_, Kc_;
  double Kc_norm_ = 0;  // Kc's largest absolute row sum
};

}  // namespace rccm

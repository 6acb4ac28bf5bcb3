// The bipotential contact solver of De Saxce and Feng at fixed beta (docs/MODEL.md s5):
// pair-wise Uzawa predictor-corrector,
//   tau = Rbar - rho_i s_i(u),   Rbar = proj(tau, K_mubar)      (paper eqs. 35-38)
// on the condensed problem of ContactProblem, swept pair by pair (Gauss-Seidel) or all at
// once (the paper's Jacobi form). The adhesive spring stays inside the pair-wise solve
// (a dim x dim matter), so a change of beta costs nothing global. From a warm start, exact
// active-set steps come first (active_set.hpp).
//
// The pairs' local algebra runs on fixed-size vectors of the dimension (2 or 3), chosen
// once per solve: run-time sized local vectors cost a third more time on B1.
#pragma once

#include "rccm/contact/active_set.hpp"
#include "rccm/contact/anderson.hpp"
#include "rccm/contact/contact_solver.hpp"
#include "rccm/contact/pair_block.hpp"
#include "rccm/la/blas_threads.hpp"
#include "rccm/la/thread_choice.hpp"

namespace rccm {

class BipotentialSolver final : public ContactSolver {
 public:
  explicit BipotentialSolver(const SolverParams& params)
      : params_(params) {}

  std::string failure_advice() const override;
  void forget_W0() override {
    active_set_2d_.forget();
    active_set_3d_.forget();
  }

 private:
  ContactSolution solve_loaded(const ContactProblem& pb, const Eigen::VectorXd& Rbar_start,
                               const Eigen::VectorXd& u_start) override;
  template <int dim>
  class Iteration;
  template <int dim>
  ContactSolution solve_in(const ContactProblem& pb, const Eigen::VectorXd& Rbar_start, const Eigen::VectorXd& u_start);
  SolverParams params_;
  // The exact step's factorization, reused while the status pattern repeats from one solve
  // to the next (a cache: results do not depend on it beyond the tolerance).
  ActiveSetSystem<2> active_set_2d_;
  ActiveSetSystem<3> active_set_3d_;
  template <int dim>
  ActiveSetSystem<dim>& active_set();
  // The vectors a solve fills, kept from one solve to the next for their memory only (every
  // solve sets them afresh): allocating them was a third of a cold solve of a few pairs.
  template <int dim>
  struct Buffers {
    std::vector<PairBlock<dim>> blocks;
    Eigen::VectorXd E, R_projected, Rbar_in, y_in;
    Verification check;
    Pattern pattern, tried, previous, solved;
    AndersonMixing anderson{0};
  };
  Buffers<2> buffers_2d_;
  Buffers<3> buffers_3d_;
  template <int dim>
  Buffers<dim>& buffers();
  // How many threads share the compressed W0's sweeps, by their speed (la/thread_choice.hpp).
  ThreadChoice threads_{blas_threads::most_products()};
};

}  // namespace rccm

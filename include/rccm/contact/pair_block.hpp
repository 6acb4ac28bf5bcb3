// What every contact solver needs of one contact pair at fixed beta, and the verifying pass
// they share (docs/MODEL.md s4-s5). With c = M (u_i - W_ii y_i) (the other pairs'
// contribution), the pair's displacement as a function of its own Rbar is u_i = Wb Rbar + c,
// where M = (I - W_ii E_i)^-1 and Wb = M W_ii: the pair's flexibility with its spring folded in.
#pragma once

#include "rccm/base/config.hpp"
#include "rccm/contact/contact_problem.hpp"

#include <Eigen/Core>

#include <vector>

namespace rccm {

/// Pair i's dim components of a stacked interface vector (layout.hpp), as a fixed-size view.
template <int dim, class V>
auto pair(V& v, int i) {
  return v.template segment<dim>(Eigen::Index(dim) * i);
}

/// The largest eigenvalue of a symmetric 1 x 1, 2 x 2 (closed form) or 3 x 3 matrix.
double largest_eigenvalue(const Eigen::Matrix<double, 1, 1>& S);
double largest_eigenvalue(const Eigen::Matrix2d& S);
double largest_eigenvalue(const Eigen::Matrix3d& S);

template <int dim>
struct PairBlock {
  using Vec = Eigen::Matrix<double, dim, 1>;
  using Mat = Eigen::Matrix<double, dim, dim>;
  Mat Wii;          // diagonal block of W0
  Vec E;            // Dref - D(beta)
  Mat M, Wb;        // (I - W_ii E)^-1 and the effective flexibility
  Vec shift;        // (-u_ref,t, g0): u_i + shift = (du_t, g), the slip and the gap
  double mubar;     // mu (1 - beta)
  double rho;       // predictor step, N/mm (paper eq. 34, or 1 / lambda_max(Wb))
  bool prescribed;  // every component prescribed: u_i does not depend on Rbar_i, Rbar_i = 0
  unsigned held;    // bit k: component k prescribed (a support on the contact node): u_i,k does not
                    // depend on Rbar, which the exact step sets to 0 there (the support carries it)

  /// The predictor of paper eq. 35 at local displacement u_i: tau = R - rho s(u_i).
  Vec predictor(const Vec& R, const Vec& u_i) const { return R - rho * modified_velocity(u_i + shift, mubar); }
};

/// Every pair's block, into `blocks` (its memory reused). Throws SolveError naming the pair
/// that has no stiffness left.
template <int dim>
void make_blocks(const ContactProblem& pb, RhoRule rule, std::vector<PairBlock<dim>>& blocks);
template <int dim>
std::vector<PairBlock<dim>> make_blocks(const ContactProblem& pb, RhoRule rule) {
  std::vector<PairBlock<dim>> blocks;
  make_blocks(pb, rule, blocks);
  return blocks;
}

/// Pair i's local problem with the other pairs held (docs/MODEL.md s5): find Rbar_i with
/// u_i = Wb Rbar_i + c and Rbar_i = proj(Rbar_i - rho s(u_i), K_mubar).
/// `iterate_pair`: the predictor-corrector (paper eqs. 35-38) iterated from R, at most
/// `max_steps` times, until a step changes R by at most `relative` max(|R|, force) + noise.
/// `solve_pair`: in 2D the exact solution of the pair's case (separated, stick, or slide
/// either way: each a 2 x 2 linear problem and its consistency conditions); in 3D, or where
/// no case fits (a pair with a prescribed component), `iterate_pair`.
/// Both update R and return the pair's status.
template <int dim>
Status iterate_pair(const PairBlock<dim>& b, const typename PairBlock<dim>::Vec& c, typename PairBlock<dim>::Vec& R,
                    int max_steps, double relative, double force, double noise);
template <int dim>
Status solve_pair(const PairBlock<dim>& b, const typename PairBlock<dim>::Vec& c, typename PairBlock<dim>::Vec& R,
                  int max_steps, double relative, double force, double noise);

/// A predictor-corrector pass at (Rbar, u) that changes nothing (docs/MODEL.md s5): each
/// pair's branch and projection proj(Rbar_i - rho s(u_i)), and the largest natural-map
/// residual |Rbar_i - proj(...)| scaled by the pair's force level (at least `floor`).
struct Verification {
  double residual = 0;
  int worst_node = -1;
  std::vector<Status> branch;
  Eigen::VectorXd projected;  // in the cone by construction: a converged solve's Rbar
};
/// The problem's force level: the largest |Rbar| or |Radh| = |D(beta) u| component (at least
/// 1e-300), the scale of the verifying pass and of a sweep's change of Rbar.
double force_level(const ContactProblem& pb, const Eigen::VectorXd& Rbar, const Eigen::VectorXd& u);

/// The pass into `v` (its vectors reused); `force`: force_level(pb, Rbar, u), which the
/// callers have at hand.
template <int dim>
void verify_pass(const ContactProblem& pb, const std::vector<PairBlock<dim>>& blocks, const Eigen::VectorXd& Rbar,
                 const Eigen::VectorXd& u, double force, double floor, Verification& v);

}  // namespace rccm

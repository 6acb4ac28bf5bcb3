#include "rccm/contact/rccm_solver.hpp"

#include "rccm/base/errors.hpp"
#include "rccm/contact/pair_block.hpp"
#include "rccm/contact/solver_tuning.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

namespace rccm {

namespace {

/// What a PSOR sweep needs of pair i beyond its block (docs/solvers/rccm.md eqs. 4-5): the
/// inverse diagonal stiffnesses of K = Kc - E, prescribed rows and columns out.
template <int dim>
struct PsorStep {
  using Vec = Eigen::Matrix<double, dim, 1>;
  using Mat = Eigen::Matrix<double, dim, dim>;
  Vec free;       // 1 for a component Rbar moves, 0 for a prescribed one (its W0 row is zero)
  double inv_Kn;  // 1 / K_nn; 0 if prescribed
  double inv_Kt;  // 1 / lambda_max(K_tt) (2D: 1 / K_tt)

  PsorStep(const ContactProblem& pb, const PairBlock<dim>& b, const Eigen::MatrixXd& K, int i) {
    const Eigen::Index o = pb.layout.offset(i);
    const double tiny = tuning::prescribed_pair * pb.W0->diagonal_scale();
    for (int k = 0; k < dim; ++k) free[k] = b.Wii(k, k) > tiny ? 1.0 : 0.0;
    const Mat Ki = free.asDiagonal() * (K.block<dim, dim>(o, o) - Mat(b.E.asDiagonal())) * free.asDiagonal();
    const double Kn = Ki(dim - 1, dim - 1);
    const double Kt = largest_eigenvalue(Eigen::Matrix<double, dim - 1, dim - 1>(Ki.template topLeftCorner<dim - 1, dim - 1>()));
    inv_Kn = Kn > 0 ? 1.0 / Kn : 0.0;
    inv_Kt = Kt > 0 ? 1.0 / Kt : 0.0;
  }
};

}  // namespace

/// The state of one solve: the interface displacement u, the gradient Rbar = Kc (u - q0) - E u
/// of the smooth part of the Tresca energy (the contact force that u implies, eq. 2), and
/// the sliding thresholds s of the current Tresca problem.
template <int dim>
class RccmSolver::Iteration {
  using Vec = Eigen::Matrix<double, dim, 1>;
  using TangentVec = Eigen::Matrix<double, dim - 1, 1>;

 public:
  Iteration(const ContactProblem& pb, const SolverParams& params, const Eigen::MatrixXd& Kc, double Kc_norm,
            const Eigen::VectorXd& Rbar_start, const Eigen::VectorXd& u_start)
      : pb_(pb), params_(params), Kc_(Kc), Kc_norm_(Kc_norm), E_(pb.Dref - pb.Dbeta),
        blocks_(make_blocks<dim>(pb, params.rho)), free_(pb.W0->size()) {
    const Eigen::Index m = pb.W0->size();
    steps_.reserve(pb.size());
    for (int i = 0; i < pb.size(); ++i) {
      steps_.emplace_back(pb, blocks_[i], Kc, i);
      pair<dim>(free_, i) = steps_.back().free;
    }
    // Warm start as the bipotential solver's: the previous (Rbar, u) give y = Rbar + E u,
    // held under the new load, u = W0 y + q0.
    s.y = Rbar_start.size() == m ? Rbar_start : Eigen::VectorXd::Zero(m);
    if (u_start.size() == m) s.y += E_.cwiseProduct(u_start);
    s.u.resize(m);
    pb.W0->multiply(s.y, s.u);
    s.u += pb.q0;
    refresh();
    s.status.assign(pb.size(), Status::Separated);
    threshold_.resize(pb.size());
  }

  ContactSolution s;

  /// The sliding thresholds of the next Tresca problem from the current normal forces (eq. 3).
  void update_thresholds() {
    for (int i = 0; i < pb_.size(); ++i) threshold_[i] = blocks_[i].mubar * std::max(s.Rbar[pb_.layout.normal(i)], 0.0);
  }

  /// One PSOR sweep of the Tresca problem (eqs. 4-5), pair after pair, component after
  /// component, the gradient following each move. Returns the largest change of Rbar over the
  /// sweep relative to the force scale (the bipotential solver's change criterion).
  double sweep() {
    const Eigen::VectorXd R_old = s.Rbar;
    const double omega = params_.over_relaxation;
    for (int i = 0; i < pb_.size(); ++i) {
      if (blocks_[i].prescribed) continue;
      const PsorStep<dim>& b = steps_[i];
      const Vec& shift = blocks_[i].shift;
      const Eigen::Index o = pb_.layout.offset(i), n = pb_.layout.normal(i);
      // Normal: relaxed step, projection on the gap g = g0 + u_n >= 0 (eq. 4).
      if (b.inv_Kn > 0) move(n, std::max(-pb_.g0[i], s.u[n] - omega * b.inv_Kn * s.Rbar[n]) - s.u[n]);
      // Tangential: the minimizer of the quadratic model plus s_i |du_t| (a shrinkage of the
      // slip towards 0 by s_i / k_t, k_t = lambda_max(K_tt)), relaxed (eq. 5).
      if (b.inv_Kt > 0) {
        const TangentVec slip = s.u.template segment<dim - 1>(o) + shift.template head<dim - 1>() -
                                b.inv_Kt * s.Rbar.template segment<dim - 1>(o);
        const double norm = slip.norm(), cut = threshold_[i] * b.inv_Kt;
        const TangentVec shrunk = norm > cut ? TangentVec((1 - cut / norm) * slip) : TangentVec::Zero();
        const TangentVec step =
            omega * (shrunk - shift.template head<dim - 1>() - s.u.template segment<dim - 1>(o));
        for (int k = 0; k < dim - 1; ++k)
          if (b.free[k] > 0) move(o + k, step[k]);
      }
    }
    return (s.Rbar - R_old).cwiseAbs().maxCoeff() / std::max(force_scale(), noise_floor() / params_.tolerance);
  }

  /// Rbar = Kc (u - q0) - E u afresh (the moves' updates accumulate round-off), 0 at the
  /// prescribed components; y = Rbar + E u.
  void refresh() {
    s.Rbar.noalias() = Kc_ * (s.u - pb_.q0);
    s.Rbar = (s.Rbar - E_.cwiseProduct(s.u)).cwiseProduct(free_);
    s.y = s.Rbar + E_.cwiseProduct(s.u);
  }

  /// The verifying pass at (Rbar, u) (pair_block.hpp, docs/MODEL.md s5): the worst scaled
  /// natural-map residual, each pair's branch as its status. Within the tolerance, as for the
  /// bipotential solver, its projections are the result (exactly 0 where separated, in the
  /// cone; they differ from the gradient by the residual).
  bool verified() {
    Verification check;
    verify_pass<dim>(pb_, blocks_, s.Rbar, s.u, force_level(pb_, s.Rbar, s.u), noise_floor() / params_.tolerance, check);
    s.residual = check.residual;
    s.worst_node = check.worst_node;
    s.status = check.branch;
    if (s.residual > params_.tolerance) return false;
    s.converged = true;
    s.Rbar = check.projected;
    s.y = s.Rbar + E_.cwiseProduct(s.u);
    return true;
  }

 private:
  /// u_k += delta, and the gradient with it: Rbar += (Kc - E) e_k delta (eq. 2).
  void move(Eigen::Index k, double delta) {
    if (delta == 0) return;
    s.u[k] += delta;
    s.Rbar.noalias() += Kc_.col(k) * delta;
    s.Rbar[k] -= E_[k] * delta;
  }
  double force_scale() const {
    return std::max(s.Rbar.cwiseAbs().maxCoeff(), pb_.Dbeta.cwiseProduct(s.u).cwiseAbs().maxCoeff());
  }
  /// The attainable accuracy of Rbar = Kc (u - q0) - E u, this many eps times its terms
  /// (the bipotential solver's floor of both criteria, for its Rbar = y - E u): u - q0 and
  /// the product cancel where the forces are small against the stiffness times u.
  double noise_floor() const {
    const double terms = Kc_norm_ * std::max(s.u.cwiseAbs().maxCoeff(), pb_.q0.cwiseAbs().maxCoeff()) +
                         E_.cwiseProduct(s.u).cwiseAbs().maxCoeff();
    return tuning::cancellation_floor * std::numeric_limits<double>::epsilon() * terms;
  }

  const ContactProblem& pb_;
  const SolverParams& params_;
  const Eigen::MatrixXd& Kc_;
  const double Kc_norm_;  // its largest absolute row sum
  const Eigen::VectorXd E_;
  const std::vector<PairBlock<dim>> blocks_;
  Eigen::VectorXd free_;  // 1 per component Rbar moves, 0 per prescribed one
  std::vector<PsorStep<dim>> steps_;
  Eigen::VectorXd threshold_;  // s_i of the current Tresca problem
};

const Eigen::MatrixXd& RccmSolver::stiffness(const ContactProblem& pb) {
  const Eigen::MatrixXd* W0 = pb.W0->dense();
  if (!W0) throw SolveError("the rccm solver inverts W0 and needs it dense; this W0 is sparse or compressed: use solver.method = \"bipotential\"");
  if (W0_.rows() == W0->rows() && W0_ == *W0) return Kc_;
  // A prescribed component (its row and column of W0 zero) gets a unit flexibility of its
  // own: the inverse exists, and the sweeps never move that component.
  Eigen::MatrixXd A = *W0;
  const double tiny = tuning::prescribed_pair * pb.W0->diagonal_scale();
  for (Eigen::Index k = 0; k < A.rows(); ++k)
    if (A(k, k) <= tiny) A(k, k) = 1.0;
  const Eigen::LLT<Eigen::MatrixXd> llt(A);
  // A finite-element W0 always is (each contact pair holds its own DOFs); a multibody
  // problem with more contact rows than degrees of freedom is not: no interface stiffness.
  if (llt.info() != Eigen::Success)
    throw SolveError("the rccm solver works on the interface displacements and needs W0 positive definite; "
                     "this W0 is singular (more contact rows than degrees of freedom): use solver.method = "
                     "\"bipotential\" or \"newton\"");
  W0_ = *W0;
  Kc_ = llt.solve(Eigen::MatrixXd::Identity(A.rows(), A.cols()));
  Kc_ = 0.5 * (Kc_ + Kc_.transpose()).eval();
  Kc_norm_ = Kc_.cwiseAbs().rowwise().sum().maxCoeff();
  return Kc_;
}

ContactSolution RccmSolver::solve_loaded(const ContactProblem& pb, const Eigen::VectorXd& Rbar_start,
                                        const Eigen::VectorXd& u_start) {
  return pb.layout.dim == 2 ? solve_in<2>(pb, Rbar_start, u_start) : solve_in<3>(pb, Rbar_start, u_start);
}

template <int dim>
ContactSolution RccmSolver::solve_in(const ContactProblem& pb, const Eigen::VectorXd& Rbar_start,
                                     const Eigen::VectorXd& u_start) {
  const Eigen::MatrixXd& Kc = stiffness(pb);
  Iteration<dim> it(pb, params_, Kc, Kc_norm_, Rbar_start, u_start);
  ContactSolution& s = it.s;
  // The fixed point on the sliding threshold (eq. 3): each Tresca problem is swept until a
  // sweep changes no force by more than the tolerance; then the Coulomb residual says whether
  // its thresholds were the solution's (eq. 6), else they are updated from its normal forces (eq. 3).
  it.update_thresholds();
  for (s.iterations = 1; s.iterations <= params_.max_iterations; ++s.iterations) {
    const double change = it.sweep();
    if (s.iterations % tuning::refresh_interval == 0) it.refresh();
    if (change > params_.tolerance) continue;
    it.refresh();
    if (it.verified()) return s;
    it.update_thresholds();
  }
  s.iterations = params_.max_iterations;
  it.refresh();
  it.verified();
  return s;
}

std::string RccmSolver::failure_advice() const {
  std::ostringstream m;
  m << "projected Gauss-Seidel converges slowly on a stiff interface: raise solver.max_iterations ("
    << params_.max_iterations << "), try another solver.over_relaxation in (1, 2) (now " << params_.over_relaxation
    << "), loosen solver.tolerance (" << params_.tolerance << "), or use solver.method = \"newton\" or \"bipotential\"";
  return m.str();
}

}  // namespace rccm

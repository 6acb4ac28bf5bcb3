#include "rccm/contact/bipotential_solver.hpp"

#include "rccm/base/errors.hpp"
#include "rccm/contact/anderson.hpp"
#include "rccm/contact/pair_block.hpp"
#include "rccm/contact/solver_tuning.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

namespace rccm {

namespace {

/// The rows of each pair in the exact step, from its status and the direction of its friction,
/// into `p` (its memory reused).
template <int dim>
void pattern_of(const std::vector<Status>& status, const std::vector<PairBlock<dim>>& blocks,
                const Eigen::VectorXd& Rbar, Pattern& p) {
  p.resize(status.size());
  for (std::size_t i = 0; i < status.size(); ++i) {
    p[i].status = blocks[i].prescribed ? Status::Separated : status[i];
    p[i].held = blocks[i].held;
    p[i].direction.setZero();
    if (p[i].status != Status::Slide) continue;
    const Eigen::Matrix<double, dim, 1> R = pair<dim>(Rbar, int(i));
    const double Rt = tangential_norm(R);
    if (Rt > 0)
      p[i].direction.head<dim - 1>() = R.template head<dim - 1>() / Rt;
    else
      p[i].direction[0] = -1.0;
  }
}

}  // namespace

/// The state of one contact solve: y = Rbar + E u, u = W0 y + q0 and Rbar (in the solution `s`),
/// the pairs' blocks, and what each pass finds (in the solver's buffers).
template <int dim>
class BipotentialSolver::Iteration {
  using Vec = Eigen::Matrix<double, dim, 1>;

 public:
  Iteration(const ContactProblem& pb, const SolverParams& params, const Eigen::VectorXd& Rbar_start,
            const Eigen::VectorXd& u_start, ContactSolution& solution, Buffers<dim>& buffers)
      : s(solution), pb_(pb), params_(params), blocks_(buffers.blocks), E_(buffers.E),
        R_projected_(buffers.R_projected), Rbar_in_(buffers.Rbar_in), y_in_(buffers.y_in), check_(buffers.check),
        cold_(Rbar_start.size() != pb.W0->size()) {
    make_blocks<dim>(pb, params.rho, blocks_);
    E_ = pb.Dref - pb.Dbeta;
    const Eigen::Index m = pb.W0->size();
    // Warm start: y from the previous Rbar and u (consistent if nothing changed), then u from y.
    s.Rbar = Rbar_start.size() == m ? Rbar_start : Eigen::VectorXd::Zero(m);
    s.y = s.Rbar;
    if (u_start.size() == m) s.y += E_.cwiseProduct(u_start);
    s.status.assign(pb.size(), Status::Separated);
    for (int i = 0; i < pb.size(); ++i)
      if (blocks_[i].prescribed) pair<dim>(s.Rbar, i).setZero(), pair<dim>(s.y, i).setZero();
    s.u.resize(m);
    refresh();
    s.Rbar = s.y - E_.cwiseProduct(s.u);
    R_projected_.setZero(m);
  }

  ContactSolution& s;

  /// A predictor-corrector pass at the current (Rbar, u) that changes nothing: each pair's
  /// branch and projection, and the largest scaled natural-map residual (pair_block.hpp).
  void verify() { verify(force_level(pb_, s.Rbar, s.u), noise_floor() / params_.tolerance); }

  /// One sweep of the predictor-corrector over every pair (paper eqs. 35-38): Gauss-Seidel
  /// updates u after each pair (docs/MODEL.md s5: far more robust), the paper's Jacobi form
  /// after the sweep. The sweep's Rbar and y on entry are kept for the convergence check
  /// and the extrapolation.
  void sweep() {
    Rbar_in_ = s.Rbar;
    y_in_ = s.y;
    const bool gauss_seidel = params_.form == SweepForm::GaussSeidel;
    const double noise = noise_floor();
    const double F_old = force_level(pb_, s.Rbar, s.u);
    // Pair i's local solve at the current u: its status and projection, and its next y.
    const auto local = [&](int i) -> Vec {
      const PairBlock<dim>& b = blocks_[i];
      const Vec c = b.M * (pair<dim>(s.u, i) - b.Wii * pair<dim>(s.y, i));
      Vec R = pair<dim>(s.Rbar, i);
      const double relative = tuning::local_tolerance_fraction * params_.tolerance;
      s.status[i] = gauss_seidel ? solve_pair<dim>(b, c, R, params_.local_iterations, relative, F_old, noise)
                                 : iterate_pair<dim>(b, c, R, 1, relative, F_old, noise);  // Jacobi: the paper's one step
      pair<dim>(R_projected_, i) = R;
      return R + b.E.cwiseProduct(Vec(b.Wb * R + c));
    };
    if (gauss_seidel) {
      gauss_seidel_pass<dim>(*pb_.W0, [&](int i) {
        if (blocks_[i].prescribed) return;
        pair<dim>(s.y, i) = local(i);
        pair<dim>(s.Rbar, i) = pair<dim>(R_projected_, i);
      }, s.y, s.u, blocks_swept_);
      return;
    }
    for (int i = 0; i < pb_.size(); ++i)  // the Jacobi form's next y (local(i) reads pair i of y only) ...
      if (!blocks_[i].prescribed) pair<dim>(s.y, i) = local(i);
    s.y = y_in_ + params_.relaxation * (s.y - y_in_);  // ... under-relaxed
  }

  /// After a sweep: Rbar = y - E u, and whether its relative change over the sweep and the
  /// scaled natural-map residual are both below the tolerance. A fresh u = W0 y + q0 every
  /// tuning::refresh_interval sweeps (Jacobi: every sweep); in between, Gauss-Seidel's
  /// incremental u differs from it by the round-off of fewer sweeps, far below the tolerance,
  /// so convergence is judged on it without another product (a tenth of a 3D solve), unless
  /// extrapolations with large weights may have amplified that round-off (mixed_u_weight).
  bool converged_after_sweep() {
    if (params_.form == SweepForm::Jacobi || s.iterations % tuning::refresh_interval == 0) refresh();
    if (!criteria_hold()) return false;
    if (u_weight_ > tuning::mixed_u_weight) {
      refresh();
      if (!criteria_hold()) return false;
    }
    s.converged = true;
    s.Rbar = R_projected_;  // in the cone by construction (y - E u differs by round-off)
    return true;
  }

  /// The verifying pass found the solution: its branches and projections are the result.
  bool verified() {
    if (s.residual > params_.tolerance) return false;
    s.converged = true;
    s.status = check_.branch;
    s.Rbar = check_.projected;
    return true;
  }

  /// Whether an exact step costs less than the sweeps still to go: with a factorization of
  /// this size at hand (a run's later solves) always; without one, when the sweeps' geometric
  /// rate of the change of Rbar predicts more than m / tuning::sweeps_per_factorization
  /// sweeps to the tolerance (a dense factorization costs about m^3 / 3 products, a sweep m^2).
  bool exact_step_pays(const ActiveSetSystem<dim>& system) const {
    if (system.pattern().size() == blocks_.size()) return true;
    const double rate = change_ / previous_change_;
    if (!(rate < 1) || change_ <= 0) return true;
    const double sweeps_left = std::log(params_.tolerance / change_) / std::log(rate);
    return sweeps_left > double(pb_.W0->size()) / tuning::sweeps_per_factorization;
  }

  /// Anderson's extrapolation after the sweep (anderson.hpp); Rbar follows.
  void accelerate(AndersonMixing& anderson) {
    u_weight_ *= 1 + anderson.mix(y_in_, s.y, s.u);
    s.Rbar = s.y - E_.cwiseProduct(s.u);
  }

  /// The pattern of the last verifying pass, and of the last sweep, into `p`.
  void verified_pattern(Pattern& p) const { pattern_of<dim>(check_.branch, blocks_, check_.projected, p); }
  void swept_pattern(Pattern& p) const { pattern_of<dim>(s.status, blocks_, s.Rbar, p); }

  /// An exact step of the active-set system for `pattern`; false if its matrix is singular.
  bool exact_step(ActiveSetSystem<dim>& system, const Pattern& pattern) {
    if (!system.solve(pb_, pattern, s.y, s.u)) return false;
    s.Rbar = s.y - E_.cwiseProduct(s.u);
    return true;
  }

 private:
  /// Rbar = y - E u cancels where beta -> 0 and the initial spring force E u is large: the
  /// attainable absolute accuracy of Rbar is about eps |y| (a floor for both criteria).
  double noise_floor() const {
    return tuning::cancellation_floor * std::numeric_limits<double>::epsilon() * s.y.cwiseAbs().maxCoeff();
  }
  void refresh() {
    pb_.W0->multiply(s.y, s.u);
    s.u += pb_.q0;
    u_weight_ = 1;
  }
  /// The verifying pass at `force` = force_level and `floor` = noise_floor() / tolerance.
  void verify(double force, double floor) {
    verify_pass<dim>(pb_, blocks_, s.Rbar, s.u, force, floor, check_);
    s.residual = check_.residual;
    s.worst_node = check_.worst_node;
  }
  /// The verifying pass costs as much as a sweep's local solves (on a sparse W0, half the
  /// sweep): it runs only once the change is below the tolerance.
  bool criteria_hold() {
    s.Rbar = s.y - E_.cwiseProduct(s.u);
    const double force = force_level(pb_, s.Rbar, s.u), floor = noise_floor() / params_.tolerance;
    const double change = (s.Rbar - Rbar_in_).cwiseAbs().maxCoeff() / std::max(force, floor);
    previous_change_ = change_;
    change_ = change;
    // A cold start's first sweep moves Rbar from nothing: its change says nothing, and one
    // sweep may have solved the problem (Siconos' NSGS stops after one on 00394).
    if (change > params_.tolerance && !(cold_ && s.iterations == 1)) return false;
    verify(force, floor);
    return s.residual <= params_.tolerance;
  }

  const ContactProblem& pb_;
  const SolverParams& params_;
  std::vector<PairBlock<dim>>& blocks_;
  Eigen::VectorXd& E_;
  Eigen::VectorXd& R_projected_;  // the projections of the last sweep: the reported Rbar
  Eigen::VectorXd &Rbar_in_, &y_in_;  // Rbar and y on entry to the last sweep
  Verification& check_;           // the last verifying pass
  double change_ = 0, previous_change_ = 0;  // relative changes of Rbar over the last two sweeps
  double u_weight_ = 1;  // how much the extrapolations since the last fresh u amplified its round-off
  // The sweeps' blocks (solver.block_sweeps); a W0 of one block's rows at most is swept
  // plainly: its block's sweeps would be plain sweeps without the convergence test between.
  const SweepBlocks blocks_swept_{pb_.W0->size() > tuning::sweep_block_rows ? params_.block_sweeps : 1,
                                  tuning::sweep_block_rows};
  const bool cold_;      // started from nothing (no Rbar given)
};

ContactSolution BipotentialSolver::solve_loaded(const ContactProblem& pb, const Eigen::VectorXd& Rbar_start,
                                               const Eigen::VectorXd& u_start) {
  return pb.layout.dim == 2 ? solve_in<2>(pb, Rbar_start, u_start) : solve_in<3>(pb, Rbar_start, u_start);
}

template <>
ActiveSetSystem<2>& BipotentialSolver::active_set<2>() {
  return active_set_2d_;
}
template <>
ActiveSetSystem<3>& BipotentialSolver::active_set<3>() {
  return active_set_3d_;
}
template <>
BipotentialSolver::Buffers<2>& BipotentialSolver::buffers<2>() {
  return buffers_2d_;
}
template <>
BipotentialSolver::Buffers<3>& BipotentialSolver::buffers<3>() {
  return buffers_3d_;
}

template <int dim>
ContactSolution BipotentialSolver::solve_in(const ContactProblem& pb, const Eigen::VectorXd& Rbar_start,
                                            const Eigen::VectorXd& u_start) {
  ContactSolution s;
  Buffers<dim>& kept = buffers<dim>();
  // A compressed W0's products in as many threads as the sweeps' timings chose
  // (la/thread_choice.hpp), for the whole solve.
  const bool timed = pb.W0->compressed() != nullptr;
  const blas_threads::Limit limit(timed ? threads_.chosen() : 0);
  Iteration<dim> it(pb, params_, Rbar_start, u_start, s, kept);
  // The exact step's dense matrices are bounded by active_set_max_nodes; compressed, by nothing.
  const bool exact = params_.active_set && (pb.W0->compressed() || (pb.size() <= params_.active_set_max_nodes && pb.W0->dense()));
  const bool gauss_seidel = params_.form == SweepForm::GaussSeidel;

  Pattern& pattern = kept.pattern;  // of a pass

  // Exact steps first (a primal-dual active-set iteration): from a warm start the pattern of
  // the nearby solution is usually still right, and one exact solve of its linear problem
  // leaves a single verifying pass. A pattern that does not settle is left to the sweeps.
  if (exact && gauss_seidel && Rbar_start.size() == pb.W0->size()) {
    Pattern& tried = kept.tried;
    tried.clear();
    for (int k = 0; k < tuning::exact_first_patterns && s.iterations < params_.max_iterations; ++k) {
      ++s.iterations;
      it.verify();
      if (it.verified()) return s;
      it.verified_pattern(pattern);
      if (pattern == tried || !it.exact_step(active_set<dim>(), pattern)) break;
      std::swap(tried, pattern);
      ++s.exact_solves;
    }
  }

  // Sweeps, each extrapolated from the last few (Anderson, anderson.hpp; plain beyond
  // tuning::anderson_sweeps, where an extrapolation may stall); once the pattern
  // repeats, an exact step for it instead (then verified by the next sweep), and again every
  // few sweeps if the same pattern persists unconverged. The warm start's pattern counts as
  // seen: the exact step may follow the first sweep.
  Pattern &previous = kept.previous, &solved = kept.solved;
  previous = active_set<dim>().pattern();
  solved.clear();
  int repeats = 0, since_exact = 0;
  const auto exact_step_due = [&] {
    if (!exact) return false;
    it.swept_pattern(pattern);
    repeats = pattern == previous ? repeats + 1 : 0;
    std::swap(previous, pattern);
    ++since_exact;
    return repeats >= 1 && (previous != solved || since_exact >= tuning::exact_step_interval) &&
           s.exact_solves < tuning::max_exact_steps && it.exact_step_pays(active_set<dim>());
  };
  AndersonMixing& anderson = kept.anderson;
  anderson.restart(gauss_seidel ? params_.anderson : 0);
  // A compressed W0's sweeps timed, and made with the count their timings chose (or probe).
  const auto sweep = [&] {
    if (!timed) return it.sweep();
    const int threads = threads_.threads();
    blas_threads::limit_products(threads);
    const auto start = std::chrono::steady_clock::now();
    it.sweep();
    threads_.record(threads, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    ++s.timed_sweeps;
    if (threads > 1) ++s.threaded_sweeps;
    blas_threads::limit_products(threads_.chosen());
  };
  for (++s.iterations; s.iterations <= params_.max_iterations; ++s.iterations) {
    sweep();
    if (it.converged_after_sweep()) break;
    if (!exact_step_due()) {
      if (s.iterations <= tuning::anderson_sweeps) it.accelerate(anderson);
      continue;
    }
    it.exact_step(active_set<dim>(), previous);  // if singular, the sweeps go on
    ++s.exact_solves;
    since_exact = 0;
    solved = previous;
  }
  if (!s.converged) {
    s.iterations = params_.max_iterations;
    it.verify();  // where it stands: the residual and its pair, for the failure message
  }
  return s;
}

std::string BipotentialSolver::failure_advice() const {
  std::ostringstream m;
  if (params_.form == SweepForm::Jacobi)
    m << "the Jacobi form diverges on strongly coupled interfaces: use solver.form = \"gauss-seidel\" "
      << "or under-relax it (solver.relaxation = 0.2 works on B2)";
  else
    m << "try solver.method = \"newton\" (it solved every stall seen so far), solver.anderson = 0 (plain sweeps), "
      << "raise solver.max_iterations, "
      << "loosen solver.tolerance (" << params_.tolerance << ") or take smaller steps";
  return m.str();
}

}  // namespace rccm

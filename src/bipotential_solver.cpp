#include "rccm/bipotential_solver.hpp"

#include "rccm/active_set.hpp"
#include "rccm/errors.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace rccm {

namespace {

using Mat2 = Eigen::Matrix2d;

/// What node i needs for its local solve, fixed during one contact solve.
/// With b = u_i - W_ii y_i (the other nodes' contribution), the node's displacement as
/// a function of its own Rbar is u_i = Wb (Rbar + E_i u_i ... ) = Wb Rbar + M b, where
/// M = (I - W_ii E_i)^-1 and Wb = M W_ii: the spring is folded in (MODEL.md s4).
struct NodeBlock {
  Mat2 Wii;    // diagonal block of W0
  Vec2 E;      // D1 - D(beta)
  Mat2 M, Wb;  // (I - W_ii E)^-1 and the effective flexibility
  double rho;  // predictor step, N/mm
  bool fixed;  // both components prescribed: u_i does not depend on Rbar_i
};

std::vector<NodeBlock> make_blocks(const ContactProblem& pb, RhoRule rule) {
  const Eigen::MatrixXd& W = *pb.W0;
  std::vector<NodeBlock> blocks(pb.size());
  const double scale = W.diagonal().cwiseAbs().maxCoeff();
  for (int i = 0; i < pb.size(); ++i) {
    NodeBlock& b = blocks[i];
    b.Wii = W.block<2, 2>(2 * i, 2 * i);
    b.E = pb.D1.segment<2>(2 * i) - pb.Dbeta.segment<2>(2 * i);
    const Mat2 A = Mat2::Identity() - b.Wii * b.E.asDiagonal();
    if (std::abs(A.determinant()) < 1e-12) {
      std::ostringstream m;
      m << "contact node " << i << " has no stiffness left (det(I - W E) = " << A.determinant()
        << "): once its adhesion is gone nothing holds the body there; restrain the body or keep beta > 0";
      throw SolveError(m.str());
    }
    b.M = A.inverse();
    b.Wb = b.M * b.Wii;
    b.Wb = 0.5 * (b.Wb + b.Wb.transpose());  // symmetric in exact arithmetic
    const double half_trace = 0.5 * (b.Wb(0, 0) + b.Wb(1, 1)), half_gap = 0.5 * (b.Wb(0, 0) - b.Wb(1, 1));
    const double lmax = half_trace + std::hypot(half_gap, b.Wb(0, 1));  // largest eigenvalue
    b.fixed = lmax <= 1e-14 * scale;
    if (b.fixed) {
      b.rho = 0;
    } else if (rule == RhoRule::Eigen) {
      b.rho = 1.0 / lmax;
    } else {  // paper eq. 34 (on the flexibility with the springs)
      const double dmin = std::min(b.Wb(0, 0), b.Wb(1, 1));
      b.rho = 1.0 / (dmin > 0 ? dmin : lmax);
    }
  }
  return blocks;
}

Vec2 modified_velocity_at(const ContactProblem& pb, int i, const Vec2& ui) {
  return modified_velocity(ui[0] - pb.ut_ref[i], pb.g0[i] + ui[1], pb.mubar[i]);
}

/// The rows of each node in the exact step, from its status and the sign of its friction.
std::vector<Rows> pattern_of(const std::vector<Status>& status, const std::vector<NodeBlock>& blocks,
                             const Eigen::VectorXd& Rbar) {
  std::vector<Rows> p(status.size());
  for (std::size_t i = 0; i < status.size(); ++i) {
    if (status[i] == Status::Separated || blocks[i].fixed)
      p[i] = Rows::Free;
    else if (status[i] == Status::Stick)
      p[i] = Rows::Stick;
    else
      p[i] = Rbar[2 * i] > 0 ? Rows::SlidePositive : Rows::SlideNegative;
  }
  return p;
}

}  // namespace

ContactSolution BipotentialSolver::solve(const ContactProblem& pb, const Eigen::VectorXd& Rbar_start,
                                         const Eigen::VectorXd& u_start) const {
  const Eigen::MatrixXd& W = *pb.W0;
  const int nc = pb.size(), m = 2 * nc;
  RCCM_VERIFY(W.rows() == m && W.cols() == m && pb.q0.size() == m, "contact problem sizes");
  const std::vector<NodeBlock> blocks = make_blocks(pb, params_.rho);
  const Eigen::VectorXd E = pb.D1 - pb.Dbeta;
  const bool gauss_seidel = params_.form == SweepForm::GaussSeidel;
  const int local_max = gauss_seidel ? params_.local_iterations : 1;  // Jacobi: the paper's one step
  const double tol = params_.tolerance;
  const int max_exact_first = 4;  // patterns tried by the exact-first phase

  ContactSolution s;
  // No load (q0 = 0, e.g. t = 0): the solution is exactly zero. Iterating towards it from a
  // warm start would shrink Rbar geometrically while its relative change stays constant.
  if (pb.q0.isZero(0.0)) {
    s.Rbar = s.y = s.u = Eigen::VectorXd::Zero(m);
    s.status.assign(nc, Status::Separated);
    s.converged = true;
    s.iterations = 0;
    return s;
  }
  // Warm start: y from the previous Rbar and u (consistent if nothing changed), then u from y.
  s.Rbar = Rbar_start.size() == m ? Rbar_start : Eigen::VectorXd::Zero(m);
  s.y = s.Rbar;
  if (u_start.size() == m) s.y += E.cwiseProduct(u_start);
  s.status.assign(nc, Status::Separated);
  for (int i = 0; i < nc; ++i)
    if (blocks[i].fixed) s.Rbar.segment<2>(2 * i).setZero(), s.y.segment<2>(2 * i).setZero();
  s.u = W * s.y + pb.q0;
  s.Rbar = s.y - E.cwiseProduct(s.u);

  // Rbar = y - E u cancels where beta -> 0 and the initial spring force E u is large: the
  // attainable absolute accuracy of Rbar is about eps |y| (a floor for both criteria).
  const auto noise_floor = [&]() { return 1e3 * std::numeric_limits<double>::epsilon() * s.y.cwiseAbs().maxCoeff(); };

  // The projections of the last sweep: in the cone by construction, they are the reported
  // Rbar (y - E u differs from them by the round-off of the cancellation above).
  Eigen::VectorXd R_projected = Eigen::VectorXd::Zero(m);
  // A predictor-corrector pass at the current (Rbar, u) that changes nothing: each node's
  // branch and projection, and the largest natural-map residual |Rbar - proj(Rbar - rho s)|
  // scaled by the node's force level. Returns the force scale of the problem.
  std::vector<Status> branch(nc, Status::Separated);
  Eigen::VectorXd R_branch = Eigen::VectorXd::Zero(m);
  const auto verifying_pass = [&]() {
    const Eigen::VectorXd Radh = -pb.Dbeta.cwiseProduct(s.u);
    const double F = std::max({s.Rbar.cwiseAbs().maxCoeff(), Radh.cwiseAbs().maxCoeff(), 1e-300});
    const double floor = noise_floor() / tol;
    s.residual = 0;
    s.worst_node = -1;
    for (int i = 0; i < nc; ++i) {
      // A node with both components prescribed takes no part: its Rbar is 0 by convention.
      const Vec2 R = blocks[i].fixed ? Vec2::Zero() : Vec2(s.Rbar.segment<2>(2 * i));
      const Vec2 tau = R - blocks[i].rho * modified_velocity_at(pb, i, s.u.segment<2>(2 * i));  // eq. 35
      branch[i] = blocks[i].fixed ? Status::Separated : cone_branch(tau, pb.mubar[i]);
      R_branch.segment<2>(2 * i) = blocks[i].fixed ? R : project_cone(tau, pb.mubar[i]);  // eqs. 36-38
      const double level = std::max({R.norm() + Radh.segment<2>(2 * i).norm(), 1e-8 * F, floor});
      const double r = (R - R_branch.segment<2>(2 * i)).norm() / level;
      if (r > s.residual || s.worst_node < 0) s.residual = r, s.worst_node = i;
    }
    return std::max(F, floor);
  };

  // Exact steps first (a primal-dual active-set iteration): from a warm start the pattern of
  // the nearby solution is usually still right, and one exact solve of its linear problem
  // leaves a single verifying pass. A pattern that does not settle in a few steps is left to
  // the Gauss-Seidel sweeps below.
  const bool exact_step = params_.active_set && nc <= params_.active_set_max_nodes;
  if (exact_step && gauss_seidel && Rbar_start.size() == m) {
    std::vector<Rows> tried;
    for (int k = 0; k < max_exact_first && s.iterations < params_.max_iterations; ++k) {
      ++s.iterations;
      verifying_pass();
      if (s.residual <= tol) {
        s.converged = true;
        s.status = branch;
        s.Rbar = R_branch;
        return s;
      }
      const std::vector<Rows> pattern = pattern_of(branch, blocks, R_branch);
      if (pattern == tried || !active_set_.solve(pb, pattern, s.y, s.u)) break;
      tried = pattern;
      ++s.exact_solves;
      s.Rbar = s.y - E.cwiseProduct(s.u);
    }
  }

  // The warm start's pattern counts as seen: the exact step may follow the first sweep.
  std::vector<Rows> previous_pattern = active_set_.pattern(), solved_pattern;
  int repeats = 0, since_exact = 0;
  const int max_exact_solves = 10;
  for (++s.iterations; s.iterations <= params_.max_iterations; ++s.iterations) {
    const Eigen::VectorXd R_old = s.Rbar;
    const double noise = noise_floor();
    const double F_old = std::max(R_old.cwiseAbs().maxCoeff(), pb.Dbeta.cwiseProduct(s.u).cwiseAbs().maxCoeff());
    Eigen::VectorXd y_new = s.y;
    for (int i = 0; i < nc; ++i) {
      const NodeBlock& b = blocks[i];
      if (b.fixed) continue;
      const Vec2 bi = s.u.segment<2>(2 * i) - b.Wii * s.y.segment<2>(2 * i);
      const Vec2 c = b.M * bi;
      Vec2 R = s.Rbar.segment<2>(2 * i);
      Vec2 ui = b.Wb * R + c;
      for (int k = 0; k < local_max; ++k) {
        const Vec2 tau = R - b.rho * modified_velocity_at(pb, i, ui);  // predictor, eq. 35
        const Vec2 R_next = project_cone(tau, pb.mubar[i]);          // corrector, eq. 36-38
        s.status[i] = cone_branch(tau, pb.mubar[i]);
        ++s.local_iterations;
        const double change = (R_next - R).norm();
        R = R_next;
        ui = b.Wb * R + c;
        if (change <= 0.1 * tol * std::max(R.norm(), F_old) + noise) break;
      }
      R_projected.segment<2>(2 * i) = R;
      const Vec2 yi = R + b.E.cwiseProduct(ui);
      if (gauss_seidel) {  // update u at once (MODEL.md s5: far more robust)
        const Vec2 dy = yi - s.y.segment<2>(2 * i);
        s.u.noalias() += W.middleCols<2>(2 * i) * dy;
        s.y.segment<2>(2 * i) = yi;
        s.Rbar.segment<2>(2 * i) = R;
      } else {
        y_new.segment<2>(2 * i) = yi;
      }
    }
    if (!gauss_seidel)  // the paper's Jacobi form: global update after the sweep
      s.y += params_.relaxation * (y_new - s.y);

    // Convergence: relative change of Rbar and the scaled natural-map residual.
    const auto evaluate = [&]() {
      s.Rbar = s.y - E.cwiseProduct(s.u);
      const double change = (s.Rbar - R_old).cwiseAbs().maxCoeff() / verifying_pass();
      return change <= tol && s.residual <= tol;
    };
    // A fresh u = W0 y + q0 drops the round-off that Gauss-Seidel's incremental updates
    // accumulate. It reads all of W0, as much as a sweep: done every 8 sweeps and to confirm
    // convergence (Jacobi has no u without it).
    const auto refresh = [&]() {
      s.u.noalias() = W * s.y;
      s.u += pb.q0;
    };
    const bool fresh = !gauss_seidel || s.iterations % 8 == 0;
    if (fresh) refresh();
    bool converged = evaluate();
    if (converged && !fresh) {
      refresh();
      converged = evaluate();
    }
    if (converged) {
      s.converged = true;
      s.Rbar = R_projected;
      break;
    }

    // Active set: once the pattern repeats, solve its linear problem exactly (then verify);
    // if the same pattern persists unconverged, refine that solve.
    const std::vector<Rows> pattern = pattern_of(s.status, blocks, s.Rbar);
    repeats = pattern == previous_pattern ? repeats + 1 : 0;
    previous_pattern = pattern;
    ++since_exact;
    if (exact_step && repeats >= 1 && (pattern != solved_pattern || since_exact >= 3) && s.exact_solves < max_exact_solves) {
      if (active_set_.solve(pb, pattern, s.y, s.u)) s.Rbar = s.y - E.cwiseProduct(s.u);
      since_exact = 0;
      solved_pattern = pattern;
      ++s.exact_solves;
    }
  }
  if (!s.converged) s.iterations = params_.max_iterations;
  return s;
}

}  // namespace rccm

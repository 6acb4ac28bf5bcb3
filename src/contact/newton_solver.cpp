#include "rccm/contact/newton_solver.hpp"

#include "rccm/base/errors.hpp"
#include "rccm/contact/pair_block.hpp"
#include "rccm/contact/solver_tuning.hpp"
#include "rccm/la/gmres.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

namespace rccm {

namespace {

// Globalization (docs/solvers/newton.md s5).
/// Armijo's sufficient decrease: accept the step t when theta(y + t dy) <= (1 - 2 c t) theta(y).
constexpr double armijo = 1e-4;
/// Halvings of the step before the Newton direction counts as failed (t >= 2^-8).
constexpr int max_halvings = 8;
/// Projected Gauss-Seidel sweeps when the Newton direction fails, before Newton resumes.
constexpr int fallback_sweeps = 2;
/// A Jacobian whose reciprocal condition number (LU estimate) is below this is singular.
constexpr double singular_jacobian = 1e-14;
/// 3D: the direction's relative residual |J dy + F| / |F| (an inexact Newton step whose error
/// is far below the quadratic term, docs/solvers/newton.md s3); the GMRES iterations
/// preconditioned by an earlier J's LU before J is factorized afresh; beyond refresh_iterations
/// J is factorized for the next steps (it drifted from the preconditioner's). The 169-pair corner
/// peel: refreshed beyond 6 / 8 / 10 / 12 iterations or never, 8.4 / 7.4 / 7.7 / 8.4 / 9.7 s.
constexpr double direction_accuracy = 1e-12;
constexpr int direction_iterations = 20;
constexpr int refresh_iterations = 8;

/// The Alart-Curnier augmentation of pair i, scale-invariant (docs/solvers/newton.md s4):
/// rho_n = 1 / Wb_nn and rho_t = 1 / lambda_max of Wb's tangential block (1 / lambda_max(Wb)
/// where a diagonal entry is not positive); 0 for a prescribed pair.
struct Augmentation {
  double rho_n = 0, rho_t = 0;
};

template <int dim>
std::vector<Augmentation> augmentations(const std::vector<PairBlock<dim>>& blocks) {
  std::vector<Augmentation> aug(blocks.size());
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    const PairBlock<dim>& b = blocks[i];
    if (b.prescribed) continue;
    const double lmax = largest_eigenvalue(b.Wb), w_n = b.Wb(dim - 1, dim - 1);
    const double w_t =
        largest_eigenvalue(Eigen::Matrix<double, dim - 1, dim - 1>(b.Wb.template topLeftCorner<dim - 1, dim - 1>()));
    aug[i].rho_n = 1.0 / (w_n > 0 ? w_n : lmax);
    aug[i].rho_t = 1.0 / (w_t > 0 ? w_t : lmax);
  }
  return aug;
}

/// The Alart-Curnier function of one pair (docs/solvers/newton.md s2) at its force R and its
/// slip and gap v = (du_t, g), with the augmented multipliers
///   sigma_n = R_n - rho_n g,  sigma_t = R_t - rho_t du_t,
///   F_n = R_n - max(0, sigma_n),  F_t = R_t - proj(sigma_t, disk of radius mubar max(0, sigma_n)),
/// and the case it is in: separated (sigma_n <= 0), stick (|sigma_t| <= mubar sigma_n) or slide.
template <int dim>
struct AlartCurnier {
  using Vec = typename PairBlock<dim>::Vec;
  using Mat = typename PairBlock<dim>::Mat;
  using Tangent = Eigen::Matrix<double, dim - 1, 1>;
  static constexpr int n = dim - 1;

  AlartCurnier(const PairBlock<dim>& b, const Augmentation& a, const Vec& R, const Vec& v) : block(b), aug(a) {
    sigma_n = R[n] - a.rho_n * v[n];
    if (b.prescribed || sigma_n <= 0) {  // separated (a prescribed pair as well): F = R
      status = Status::Separated;
      F = R;
      return;
    }
    F[n] = a.rho_n * v[n];  // R_n - sigma_n, without the cancellation
    const Tangent sigma_t = R.template head<n>() - a.rho_t * v.template head<n>();
    radius = b.mubar * sigma_n;
    norm_t = sigma_t.norm();
    if (norm_t <= radius) {  // F_t = R_t - sigma_t
      status = Status::Stick;
      F.template head<n>() = a.rho_t * v.template head<n>();
    } else {  // F_t = R_t - mubar sigma_n d
      status = Status::Slide;
      d = sigma_t / norm_t;
      F.template head<n>() = R.template head<n>() - radius * d;
    }
  }

  /// An element of the generalized Jacobian (docs/solvers/newton.md s3): A = dF/dR, B = dF/dv.
  void jacobian(Mat& A, Mat& B) const {
    using Tangential = Eigen::Matrix<double, n, n>;
    const PairBlock<dim>& b = block;
    const Augmentation& a = aug;
    A.setZero(), B.setZero();
    switch (status) {
      case Status::Separated: A.setIdentity(); return;
      case Status::Stick: B.diagonal().setConstant(a.rho_t); break;
      case Status::Slide: {
        // The derivative of d = sigma_t / |sigma_t| is (I - d d^T) / |sigma_t| (zero in 2D).
        const Tangential curvature = (radius / norm_t) * (Tangential::Identity() - d * d.transpose());
        A.template topLeftCorner<n, n>() = Tangential::Identity() - curvature;
        A.template topRightCorner<n, 1>() = -b.mubar * d;
        B.template topLeftCorner<n, n>() = a.rho_t * curvature;
        B.template topRightCorner<n, 1>() = b.mubar * a.rho_n * d;
      }
    }
    B(n, n) = a.rho_n;
  }

  const PairBlock<dim>& block;
  const Augmentation& aug;
  Vec F;
  Status status;
  double sigma_n, radius = 0, norm_t = 0;
  Tangent d = Tangent::Zero();  // the slide direction
};

}  // namespace

/// The state of one solve: y, u = W0 y + q0 and Rbar = y - E u, the pairs' blocks, and the
/// verifying pass's branches and projections.
template <int dim>
class NewtonSolver::Iteration {
  using Vec = typename PairBlock<dim>::Vec;
  using Mat = typename PairBlock<dim>::Mat;

 public:
  Iteration(const ContactProblem& pb, const SolverParams& params, const Eigen::VectorXd& Rbar_start,
            const Eigen::VectorXd& u_start)
      : pb_(pb), params_(params), blocks_(make_blocks<dim>(pb, params.rho)), aug_(augmentations(blocks_)), E_(pb.Dref - pb.Dbeta) {
    const Eigen::Index m = pb.W0->size();
    // Warm start: y from the previous Rbar and u (consistent if nothing changed), then u from y.
    s.y = Rbar_start.size() == m ? Rbar_start : Eigen::VectorXd::Zero(m);
    if (u_start.size() == m) s.y += E_.cwiseProduct(u_start);
    s.u.resize(m);
    refresh();
    s.status.assign(pb.size(), Status::Separated);
  }

  ContactSolution s;

  /// The verifying pass at (Rbar, u) (pair_block.hpp, docs/MODEL.md s5). True when its
  /// residual is within the tolerance: then its branches and projections are the result.
  bool verified() {
    // Rbar = y - E u cancels where beta -> 0: its attainable accuracy is about eps |y|.
    const double noise = tuning::cancellation_floor * std::numeric_limits<double>::epsilon() * s.y.cwiseAbs().maxCoeff();
    Verification check;
    verify_pass<dim>(pb_, blocks_, s.Rbar, s.u, force_level(pb_, s.Rbar, s.u), noise / params_.tolerance, check);
    s.residual = check.residual;
    s.worst_node = check.worst_node;
    s.status = check.branch;
    if (s.residual > params_.tolerance) return false;
    s.converged = true;
    s.Rbar = check.projected;  // in the cone by construction (y - E u differs by round-off)
    return true;
  }

  /// One Newton step on F(y) = 0 (docs/solvers/newton.md s3-s5): the direction, then an
  /// Armijo backtracking line search on theta = 1/2 |F|^2. False when the direction fails
  /// (singular Jacobian, no decrease, or no move).
  bool newton_step(ActiveSetSystem<2>& active_set, KeptJacobian& kept) {
    const Eigen::VectorXd F = function(s.y, s.u, &cases_);
    const double theta = 0.5 * F.squaredNorm();
    Eigen::VectorXd dy, du;
    if (!direction(F, active_set, kept, dy, du)) return false;
    ++s.exact_solves;
    if (!dy.allFinite() || dy.norm() <= std::numeric_limits<double>::epsilon() * s.y.norm()) return false;
    double t = 1;
    for (int k = 0; k <= max_halvings; ++k, t *= 0.5) {
      const Eigen::VectorXd y = s.y + t * dy, u = s.u + t * du;
      if (0.5 * function(y, u).squaredNorm() <= (1 - 2 * armijo * t) * theta) {
        s.y = y;
        s.u = u;
        s.Rbar = y - E_.cwiseProduct(u);
        return true;
      }
    }
    return false;
  }

  /// A projected Gauss-Seidel sweep: pair by pair, the bipotential solver's local solve
  /// (pair_block.hpp) with the other pairs held, u updated at once.
  void sweep() {
    const double F_old = force_level(pb_, s.Rbar, s.u);
    gauss_seidel_pass<dim>(*pb_.W0, [&](int i) {
      const PairBlock<dim>& b = blocks_[i];
      if (b.prescribed) return;
      const Vec c = b.M * (pair<dim>(s.u, i) - b.Wii * pair<dim>(s.y, i));
      Vec R = pair<dim>(s.Rbar, i);
      solve_pair<dim>(b, c, R, params_.local_iterations, tuning::local_tolerance_fraction * params_.tolerance, F_old, 0.0);
      pair<dim>(s.y, i) = R + b.E.cwiseProduct(Vec(b.Wb * R + c));
      pair<dim>(s.Rbar, i) = R;
    }, s.y, s.u, SweepBlocks{});
    refresh();
  }

 private:
  /// u = W0 y + q0 and Rbar = y - E u.
  void refresh() {
    pb_.W0->multiply(s.y, s.u);
    s.u += pb_.q0;
    s.Rbar = s.y - E_.cwiseProduct(s.u);
  }

  /// F at (y, u) (u = W0 y + q0), pair by pair, and each pair's case.
  Eigen::VectorXd function(const Eigen::VectorXd& y, const Eigen::VectorXd& u,
                           std::vector<AlartCurnier<dim>>* cases = nullptr) const {
    Eigen::VectorXd F(y.size());
    if (cases) cases->clear();
    for (int i = 0; i < pb_.size(); ++i) {
      const PairBlock<dim>& b = blocks_[i];
      const Vec ui = pair<dim>(u, i);
      const AlartCurnier<dim> local(b, aug_[i], Vec(pair<dim>(y, i)) - b.E.cwiseProduct(ui), ui + b.shift);
      pair<dim>(F, i) = local.F;
      if (cases) cases->push_back(local);
    }
    return F;
  }

  /// The Newton direction: J dy = -F with J = A + (B - A E) W0 (A, B block diagonal: the pairs'
  /// dF/dR and dF/dv; R = y - E u, u = W0 y + q0), and du = W0 dy. False if J is singular.
  /// 3D: by GMRES preconditioned with `kept` (an earlier J's factorization), or J factorized into it.
  bool direction(const Eigen::VectorXd& F, ActiveSetSystem<2>& active_set,
                 KeptJacobian& kept, Eigen::VectorXd& dy,
                 Eigen::VectorXd& du) {
    if constexpr (dim == 2) {
      // F is affine on the cases' piece: y + dy is the zero of its affine extension, which is
      // the solution of the active-set system of those cases (its rows are F's rows combined:
      // docs/solvers/newton.md s3). That system keeps its factorization across solves.
      (void)F;
      (void)kept;
      Pattern pattern(pb_.size());
      for (int i = 0; i < pb_.size(); ++i) {
        pattern[i].status = cases_[i].status;
        pattern[i].held = blocks_[i].held;
        if (cases_[i].status == Status::Slide) pattern[i].direction[0] = cases_[i].d[0];
      }
      Eigen::VectorXd y = s.y, u = s.u;
      if (!active_set.solve(pb_, pattern, y, u)) return false;
      dy = y - s.y;
      du = u - s.u;
    } else {
      (void)active_set;
      const Eigen::Index m = s.y.size();
      jacobian_blocks();
      const Eigen::VectorXd b = -F;
      int iterations = 0;
      if (kept.serves(m) && preconditioned(kept, b, dy, du, iterations)) {
        if (iterations > refresh_iterations) factorize(kept);
        return true;
      }
      factorize(kept);
      if (kept.hodlr) {  // J's compressed factorization, to the compression's accuracy: GMRES finishes
        if (preconditioned(kept, b, dy, du, iterations)) return true;
        kept.reset();
        return false;
      }
      if (!(kept.lu->rcond() >= singular_jacobian)) {
        kept.reset();
        return false;
      }
      dy = kept.lu->solve(b);
      du.resize(m);
      pb_.W0->multiply(dy, du);
    }
    return true;
  }

  /// 3D: J at the current cases factorized into `kept`: formed and by its LU on a dense W0,
  /// mixed from W0's compression on a compressed one.
  void factorize(KeptJacobian& kept) const {
    const HodlrMatrix* compressed = pb_.W0->compressed_preconditioner();
    if (compressed == nullptr) return kept.factorize(jacobian());
    const Eigen::Index m = s.y.size();
    Eigen::MatrixXd Cw(dim, m), Cy(dim, m);
    for (int i = 0; i < pb_.size(); ++i)
      Cw.template middleCols<dim>(Eigen::Index(dim) * i) = C_[i], Cy.template middleCols<dim>(Eigen::Index(dim) * i) = A_[i];
    kept.factorize(*compressed, Cw, Cy);
  }

  /// 3D: each pair's rows of J = A + C W0 at the current cases, C = B - A E (A, B: the pair's
  /// dF/dR and dF/dv; R = y - E u, u = W0 y + q0), into A_ and C_.
  void jacobian_blocks() {
    A_.resize(pb_.size()), C_.resize(pb_.size());
    Mat B;
    for (int i = 0; i < pb_.size(); ++i) {
      cases_[i].jacobian(A_[i], B);
      C_[i] = B - A_[i] * blocks_[i].E.asDiagonal();
    }
  }

  /// J z from z and w = W0 z, pair by pair: A_i z_i + C_i w_i.
  Eigen::VectorXd jacobian_times(const Eigen::VectorXd& z, const Eigen::VectorXd& w) const {
    Eigen::VectorXd out(z.size());
    for (int i = 0; i < pb_.size(); ++i) pair<dim>(out, i) = A_[i] * pair<dim>(z, i) + C_[i] * pair<dim>(w, i);
    return out;
  }

  /// J formed densely (3 m^2 products), for its factorization: pair i's rows C_i W0_i + A_i
  /// on its diagonal block, W0_i its rows (= columns: W0 is symmetric).
  Eigen::MatrixXd jacobian() const {
    const Eigen::Index m = s.y.size();
    const Eigen::MatrixXd& W = *pb_.W0->dense();
    Eigen::MatrixXd J(m, m);
    for (int i = 0; i < pb_.size(); ++i) {
      const Eigen::Index first = pb_.layout.offset(i);
      J.template middleRows<dim>(first).noalias() = C_[i] * W.template middleCols<dim>(first).transpose();
      J.template block<dim, dim>(first, first) += A_[i];
    }
    return J;
  }

  /// J dy = b by GMRES preconditioned with an earlier J's factorization, J applied without forming it (one
  /// product with W0 per iteration, kept: du = W0 dy is their combination): true when dy's
  /// residual, recomputed from dy and du, is within direction_accuracy |b| after
  /// direction_iterations at most (`iterations`: how many).
  bool preconditioned(const KeptJacobian& earlier, const Eigen::VectorXd& b, Eigen::VectorXd& dy,
                      Eigen::VectorXd& du, int& iterations) const {
    Eigen::MatrixXd Wz(b.size(), direction_iterations);
    int products = 0;
    const GmresResult g = gmres(
        [&](const Eigen::VectorXd& z) -> Eigen::VectorXd {
          pb_.W0->multiply(z, Wz.col(products));
          return jacobian_times(z, Wz.col(products++));
        },
        [&](const Eigen::VectorXd& v) -> Eigen::VectorXd { return earlier.solve(v); }, b, direction_accuracy,
        direction_iterations);
    iterations = g.iterations;
    if (g.iterations == 0) return false;
    const Eigen::VectorXd W_x = Wz.leftCols(g.iterations) * g.coefficients;
    if (!g.x.allFinite() || !((jacobian_times(g.x, W_x) - b).norm() <= direction_accuracy * b.norm())) return false;
    dy = g.x;
    du = W_x;
    return true;
  }

  const ContactProblem& pb_;
  const SolverParams& params_;
  const std::vector<PairBlock<dim>> blocks_;
  const std::vector<Augmentation> aug_;
  const Eigen::VectorXd E_;
  std::vector<AlartCurnier<dim>> cases_;  // at the current y
  std::vector<Mat> A_, C_;                 // 3D: the pairs' rows of J = A + C W0 at cases_
};

void NewtonSolver::KeptJacobian::factorize(const Eigen::MatrixXd& J) {
  reset();
  lu.emplace(J);
  ++factorizations;
}

void NewtonSolver::KeptJacobian::factorize(const HodlrMatrix& W0, const Eigen::MatrixXd& Cw, const Eigen::MatrixXd& Cy) {
  reset();
  mixed.emplace(W0.rows_mixed(Cw, Cy));
  hodlr.emplace(*mixed);
  ++factorizations;
}

void NewtonSolver::KeptJacobian::reset() {
  lu.reset();
  hodlr.reset();
  mixed.reset();
}

ContactSolution NewtonSolver::solve_loaded(const ContactProblem& pb, const Eigen::VectorXd& Rbar_start,
                                          const Eigen::VectorXd& u_start) {
  if (!pb.W0->dense() && !pb.W0->compressed())
    throw SolveError("the Newton contact solver needs a dense or compressed W0; this W0 is neither: use solver.method = \"bipotential\"");
  return pb.layout.dim == 2 ? solve_in<2>(pb, Rbar_start, u_start) : solve_in<3>(pb, Rbar_start, u_start);
}

template <int dim>
ContactSolution NewtonSolver::solve_in(const ContactProblem& pb, const Eigen::VectorXd& Rbar_start,
                                       const Eigen::VectorXd& u_start) {
  Iteration<dim> it(pb, params_, Rbar_start, u_start);
  ContactSolution& s = it.s;
  while (!it.verified() && s.iterations < params_.max_iterations) {
    ++s.iterations;
    if (it.newton_step(active_set_, kept_jacobian_)) continue;
    // The Newton direction failed: a few projected sweeps, then Newton from there.
    for (int k = 0; k < fallback_sweeps && s.iterations < params_.max_iterations; ++k, ++s.iterations) it.sweep();
  }
  return s;
}

std::string NewtonSolver::failure_advice() const {
  std::ostringstream m;
  m << "raise solver.max_iterations, loosen solver.tolerance (" << params_.tolerance
    << "), take smaller steps or use solver.method = \"bipotential\"";
  return m.str();
}

}  // namespace rccm

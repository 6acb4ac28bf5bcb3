#include "rccm/contact/pair_block.hpp"

#include "rccm/base/errors.hpp"
#include "rccm/contact/solver_tuning.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace rccm {

double largest_eigenvalue(const Eigen::Matrix<double, 1, 1>& S) { return S(0, 0); }
double largest_eigenvalue(const Eigen::Matrix2d& S) {
  const double half_trace = 0.5 * (S(0, 0) + S(1, 1)), half_gap = 0.5 * (S(0, 0) - S(1, 1));
  return half_trace + hypot_fast(half_gap, S(0, 1));
}
double largest_eigenvalue(const Eigen::Matrix3d& S) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  // The characteristic cubic's roots in closed form: the iterative solver took 9 % of a 3D
  // corner peel run; these lose digits where two eigenvalues nearly coincide (5e-9 relative at
  // worst, tests/contact/test_pair_block.cpp), nothing for rho, a step length.
  solver.computeDirect(S, Eigen::EigenvaluesOnly);
  return solver.eigenvalues()[2];
}

template <int dim>
void make_blocks(const ContactProblem& pb, RhoRule rule, std::vector<PairBlock<dim>>& blocks) {
  using Mat = typename PairBlock<dim>::Mat;
  blocks.resize(pb.size());  // every member of each block is set below
  const double scale = pb.W0->diagonal_scale();
  const Eigen::MatrixXd* W = pb.W0->dense();
  using Vec = typename PairBlock<dim>::Vec;
  for (int i = 0; i < pb.size(); ++i) {
    // Computed in locals and stored once: members stored and read back at once stalled on
    // store forwarding (a third of a small cold solve's time).
    const Eigen::Index first = pb.layout.offset(i);
    Mat Wii;
    if (W != nullptr)  // read in place: a copy through block()'s run-time sized matrix costs
      Wii = W->template block<dim, dim>(first, first);
    else
      Wii = pb.W0->block(first, dim);
    const Vec E = pair<dim>(pb.Dref, i) - pair<dim>(pb.Dbeta, i);
    Mat M = Mat::Identity(), Wb = Wii;  // no spring to fold in (a bonded pair whose spring W0 holds, a plain problem)
    if (!E.isZero(0.0)) {
      const Mat A = Mat::Identity() - Wii * E.asDiagonal();
      if (std::abs(A.determinant()) < tuning::singular_pair) {
        std::ostringstream m;
        m << "contact node " << i << " has no stiffness left (det(I - W E) = " << A.determinant()
          << "): once its adhesion is gone nothing holds the body there; restrain the body or keep beta > 0";
        throw SolveError(m.str(), i);
      }
      M = A.inverse();
      Wb = M * Wii;
    }
    Wb = 0.5 * (Wb + Wb.transpose()).eval();  // symmetric in exact arithmetic
    const double lmax = largest_eigenvalue(Wb);
    PairBlock<dim>& b = blocks[i];
    b.Wii = Wii;
    b.E = E;
    b.M = M;
    b.Wb = Wb;
    b.shift = -pair<dim>(pb.u_ref, i);
    b.shift[dim - 1] = pb.g0[i];
    b.mubar = pb.mubar[i];
    b.prescribed = lmax <= tuning::prescribed_pair * scale;
    b.held = 0;
    for (int k = 0; k < dim; ++k)
      if (Wii(k, k) <= tuning::prescribed_pair * scale) b.held |= 1u << k;
    if (b.prescribed) {
      b.rho = 0;
    } else if (rule == RhoRule::Eigen) {
      b.rho = 1.0 / lmax;
    } else {  // paper eq. 34 (on the flexibility with the springs)
      const double dmin = Wb.diagonal().minCoeff();
      b.rho = 1.0 / (dmin > 0 ? dmin : lmax);
    }
  }
}

namespace {

/// The 2D pair's exact solution (docs/MODEL.md s5): with d = c + shift the slip and gap at
/// R = 0, v = Wb R + d must be (du_t, g) with
///   separated: R = 0, g >= 0;   stick: v = 0, |R_t| <= mubar R_n;
///   slide: g = 0, R_t = -sigma mubar R_n, R_n >= 0, sigma du_t >= 0 (sigma = +-1).
/// False when no case fits (Wb singular: a prescribed component).
bool solve_pair_exactly(const PairBlock<2>& b, const Eigen::Vector2d& c, Eigen::Vector2d& R, Status& status) {
  const Eigen::Vector2d d = c + b.shift;
  if (d[1] >= 0) {
    R.setZero();
    status = Status::Separated;
    return true;
  }
  const double det = b.Wb.determinant();
  if (!(det > 1e-12 * b.Wb.squaredNorm())) return false;
  const Eigen::Vector2d stick = -b.Wb.inverse() * d;
  if (stick[1] >= 0 && std::abs(stick[0]) <= b.mubar * stick[1]) {
    R = stick;
    status = Status::Stick;
    return true;
  }
  for (double sigma : {1.0, -1.0}) {
    const Eigen::Vector2d a(-sigma * b.mubar, 1.0);  // R = R_n a
    const double Wa_n = b.Wb.row(1).dot(a);
    if (!(Wa_n > 0)) continue;
    const double Rn = -d[1] / Wa_n;
    if (sigma * (b.Wb.row(0).dot(a) * Rn + d[0]) < 0) continue;
    R = Rn * a;
    status = Status::Slide;
    return true;
  }
  return false;
}

}  // namespace

template <int dim>
Status iterate_pair(const PairBlock<dim>& b, const typename PairBlock<dim>::Vec& c, typename PairBlock<dim>::Vec& R,
                    int max_steps, double relative, double force, double noise) {
  using Vec = typename PairBlock<dim>::Vec;
  Status status = Status::Separated;
  Vec ui = b.Wb * R + c;
  for (int k = 0; k < max_steps; ++k) {
    const Vec tau = b.predictor(R, ui);             // predictor, eq. 35
    const Vec R_next = project_cone(tau, b.mubar);  // corrector, eqs. 36-38
    status = cone_branch(tau, b.mubar);
    const double change = (R_next - R).norm();
    R = R_next;
    ui = b.Wb * R + c;
    if (change <= relative * std::max(R.norm(), force) + noise) break;
  }
  return status;
}

template <int dim>
Status solve_pair(const PairBlock<dim>& b, const typename PairBlock<dim>::Vec& c, typename PairBlock<dim>::Vec& R,
                  int max_steps, double relative, double force, double noise) {
  if constexpr (dim == 2) {
    Status status;
    if (solve_pair_exactly(b, c, R, status)) return status;
  }
  return iterate_pair(b, c, R, max_steps, relative, force, noise);
}

double force_level(const ContactProblem& pb, const Eigen::VectorXd& Rbar, const Eigen::VectorXd& u) {
  return std::max({Rbar.cwiseAbs().maxCoeff(), pb.Dbeta.cwiseProduct(u).cwiseAbs().maxCoeff(), 1e-300});
}

template <int dim>
void verify_pass(const ContactProblem& pb, const std::vector<PairBlock<dim>>& blocks, const Eigen::VectorXd& Rbar,
                 const Eigen::VectorXd& u, double force, double floor, Verification& v) {
  using Vec = typename PairBlock<dim>::Vec;
  v.residual = 0;
  v.worst_node = -1;
  v.branch.resize(pb.size());
  v.projected.resize(Rbar.size());
  for (int i = 0; i < pb.size(); ++i) {
    const PairBlock<dim>& b = blocks[i];
    // A pair with every component prescribed takes no part: its Rbar is 0 by convention.
    const Vec R = b.prescribed ? Vec::Zero() : Vec(pair<dim>(Rbar, i));
    const Vec tau = b.predictor(R, pair<dim>(u, i));  // eq. 35
    v.branch[i] = b.prescribed ? Status::Separated : cone_branch(tau, b.mubar);
    pair<dim>(v.projected, i) = b.prescribed ? R : project_cone(tau, b.mubar);  // eqs. 36-38
    const Vec Radh = pair<dim>(pb.Dbeta, i).cwiseProduct(pair<dim>(u, i));  // -Radh: the same norm
    const double level = std::max({R.norm() + Radh.norm(), tuning::residual_level_floor * force, floor});
    const double r = (R - pair<dim>(v.projected, i)).norm() / level;
    if (r > v.residual || v.worst_node < 0) v.residual = r, v.worst_node = i;
  }
}

template void make_blocks<2>(const ContactProblem&, RhoRule, std::vector<PairBlock<2>>&);
template void make_blocks<3>(const ContactProblem&, RhoRule, std::vector<PairBlock<3>>&);
template Status iterate_pair<2>(const PairBlock<2>&, const Eigen::Vector2d&, Eigen::Vector2d&, int, double, double,
                                double);
template Status iterate_pair<3>(const PairBlock<3>&, const Eigen::Vector3d&, Eigen::Vector3d&, int, double, double,
                                double);
template Status solve_pair<2>(const PairBlock<2>&, const Eigen::Vector2d&, Eigen::Vector2d&, int, double, double,
                              double);
template Status solve_pair<3>(const PairBlock<3>&, const Eigen::Vector3d&, Eigen::Vector3d&, int, double, double,
                              double);
template void verify_pass<2>(const ContactProblem&, const std::vector<PairBlock<2>>&, const Eigen::VectorXd&,
                             const Eigen::VectorXd&, double, double, Verification&);
template void verify_pass<3>(const ContactProblem&, const std::vector<PairBlock<3>>&, const Eigen::VectorXd&,
                             const Eigen::VectorXd&, double, double, Verification&);

}  // namespace rccm

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
  return half_trace + std::hypot(half_gap, S(0, 1));
}
double largest_eigenvalue(const Eigen::Matrix3d& S) {
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(S, Eigen::EigenvaluesOnly).eigenvalues()[2];
}

template <int dim>
std::vector<PairBlock<dim>> make_blocks(const ContactProblem& pb, RhoRule rule) {
  using Mat = typename PairBlock<dim>::Mat;
  std::vector<PairBlock<dim>> blocks;
  blocks.reserve(pb.size());
  const double scale = pb.W0->diagonal_scale();
  for (int i = 0; i < pb.size(); ++i) {
    PairBlock<dim> b;  // default-initialized: every member is set below
    b.Wii = pb.W0->block(pb.layout.offset(i), dim);
    b.E = pair<dim>(pb.D1, i) - pair<dim>(pb.Dbeta, i);
    b.shift = -pair<dim>(pb.u_ref, i);
    b.shift[dim - 1] = pb.g0[i];
    b.mubar = pb.mubar[i];
    const Mat A = Mat::Identity() - b.Wii * b.E.asDiagonal();
    if (std::abs(A.determinant()) < tuning::singular_pair) {
      std::ostringstream m;
      m << "contact node " << i << " has no stiffness left (det(I - W E) = " << A.determinant()
        << "): once its adhesion is gone nothing holds the body there; restrain the body or keep beta > 0";
      throw SolveError(m.str());
    }
    b.M = A.inverse();
    b.Wb = b.M * b.Wii;
    b.Wb = 0.5 * (b.Wb + b.Wb.transpose());  // symmetric in exact arithmetic
    const double lmax = largest_eigenvalue(b.Wb);
    b.prescribed = lmax <= tuning::prescribed_pair * scale;
    if (b.prescribed) {
      b.rho = 0;
    } else if (rule == RhoRule::Eigen) {
      b.rho = 1.0 / lmax;
    } else {  // paper eq. 34 (on the flexibility with the springs)
      const double dmin = b.Wb.diagonal().minCoeff();
      b.rho = 1.0 / (dmin > 0 ? dmin : lmax);
    }
    blocks.push_back(b);
  }
  return blocks;
}

template <int dim>
Verification verify_pass(const ContactProblem& pb, const std::vector<PairBlock<dim>>& blocks,
                         const Eigen::VectorXd& Rbar, const Eigen::VectorXd& u, double floor) {
  using Vec = typename PairBlock<dim>::Vec;
  const Eigen::VectorXd Radh = -pb.Dbeta.cwiseProduct(u);
  const double F = std::max({Rbar.cwiseAbs().maxCoeff(), Radh.cwiseAbs().maxCoeff(), 1e-300});
  Verification v;
  v.branch.assign(pb.size(), Status::Separated);
  v.projected = Eigen::VectorXd::Zero(Rbar.size());
  for (int i = 0; i < pb.size(); ++i) {
    const PairBlock<dim>& b = blocks[i];
    // A pair with every component prescribed takes no part: its Rbar is 0 by convention.
    const Vec R = b.prescribed ? Vec::Zero() : Vec(pair<dim>(Rbar, i));
    const Vec tau = b.predictor(R, pair<dim>(u, i));  // eq. 35
    v.branch[i] = b.prescribed ? Status::Separated : cone_branch(tau, b.mubar);
    pair<dim>(v.projected, i) = b.prescribed ? R : project_cone(tau, b.mubar);  // eqs. 36-38
    const double level = std::max({R.norm() + pair<dim>(Radh, i).norm(), tuning::residual_level_floor * F, floor});
    const double r = (R - pair<dim>(v.projected, i)).norm() / level;
    if (r > v.residual || v.worst_node < 0) v.residual = r, v.worst_node = i;
  }
  v.force_scale = std::max(F, floor);
  return v;
}

template std::vector<PairBlock<2>> make_blocks<2>(const ContactProblem&, RhoRule);
template std::vector<PairBlock<3>> make_blocks<3>(const ContactProblem&, RhoRule);
template Verification verify_pass<2>(const ContactProblem&, const std::vector<PairBlock<2>>&, const Eigen::VectorXd&,
                                     const Eigen::VectorXd&, double);
template Verification verify_pass<3>(const ContactProblem&, const std::vector<PairBlock<3>>&, const Eigen::VectorXd&,
                                     const Eigen::VectorXd&, double);

}  // namespace rccm

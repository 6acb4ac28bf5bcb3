// Random condensed contact problems for the solvers' tests, and the check that a solution
// satisfies the condensed equations and the law.
#pragma once

#include "rccm/contact/contact_problem.hpp"
#include "rccm/contact/delassus.hpp"

#include <Eigen/Dense>
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

namespace rccm::testing {

/// Random problem families: `Mild`: W = B B^T / m + I (diagonally dominant like an FE
/// Delassus matrix), loads of either sign, mubar <= 0.4; `Hard`: W = B B^T / m + 0.01 I
/// (condition number ~ 100, every pair coupled to every other), loads pressing the pairs into
/// contact, three times as much shear (most pairs slide), mubar up to 1.
enum class Family { Mild, Hard };

/// A random condensed problem of n pairs of `dim` components, without or with springs Dref
/// folded into W0 = (W^-1 + Dref)^-1 and D(beta) <= Dref.
struct RandomProblem {
  RandomProblem(int n, int dim, Family family, bool springs, std::mt19937& gen) {
    std::uniform_real_distribution<double> U(-1, 1), P(0, 1);
    const bool hard = family == Family::Hard;
    const int m = dim * n;
    pb.layout.dim = dim;
    const Eigen::MatrixXd B = Eigen::MatrixXd::NullaryExpr(m, m, [&]() { return U(gen); });
    Eigen::MatrixXd Wd = B * B.transpose() / double(m) + (hard ? 0.01 : 1.0) * Eigen::MatrixXd::Identity(m, m);
    pb.q0 = Eigen::VectorXd::NullaryExpr(m, [&]() { return U(gen); });
    if (hard)
      for (int i = 0; i < n; ++i) {
        pb.q0.segment(dim * i, dim - 1) *= 3.0;
        pb.q0[dim * i + dim - 1] -= 0.5;
      }
    pb.mubar = Eigen::VectorXd::NullaryExpr(n, [&]() { return (hard ? 1.0 : 0.4) * P(gen); });
    pb.g0 = Eigen::VectorXd::Zero(n);
    pb.u_ref = Eigen::VectorXd::NullaryExpr(m, [&]() { return 0.1 * U(gen); });
    pb.Dref = pb.Dbeta = Eigen::VectorXd::Zero(m);
    if (springs) {
      pb.Dref = Eigen::VectorXd::NullaryExpr(m, [&]() { return 2.0 * P(gen); });
      for (int i = 0; i < n; ++i) {
        const double beta = P(gen);
        pb.Dbeta.segment(dim * i, dim) = beta * beta * pb.Dref.segment(dim * i, dim);
      }
      Wd = (Wd.inverse() + Eigen::MatrixXd(pb.Dref.asDiagonal())).inverse();
      Wd = 0.5 * (Wd + Wd.transpose()).eval();
    }
    W = DenseDelassus(Wd);
    pb.W0 = &W;
  }
  RandomProblem(const RandomProblem&) = delete;
  const Eigen::MatrixXd& matrix() const { return *W.dense(); }

  DenseDelassus W{Eigen::MatrixXd()};
  ContactProblem pb;
};

/// One step of the drift between two solves of a run (as between the integrator's stages):
/// the load q0 by up to 0.05, each spring D(beta) by up to 2 % (within [0, Dref]), mubar up
/// by 0.005 (at most mubar_max).
inline void drift(ContactProblem& pb, double mubar_max, std::mt19937& gen) {
  std::uniform_real_distribution<double> U(-1, 1);
  pb.q0 += 0.05 * Eigen::VectorXd::NullaryExpr(pb.q0.size(), [&]() { return U(gen); });
  for (Eigen::Index c = 0; c < pb.Dbeta.size(); ++c)
    pb.Dbeta[c] = std::clamp(pb.Dbeta[c] * (1 + 0.02 * U(gen)), 0.0, pb.Dref[c]);
  pb.mubar = (pb.mubar.array() + 0.005).min(mubar_max);
}

/// The solution satisfies the condensed equations u = W0 (Rbar + E u) + q0 and the law
/// (Signorini, Coulomb, complementarity: relative residuals).
inline void require_solution(const ContactProblem& pb, const ContactSolution& s) {
  const Eigen::VectorXd y = s.Rbar + (pb.Dref - pb.Dbeta).cwiseProduct(s.u);
  Eigen::VectorXd Wy(y.size());
  pb.W0->multiply(y, Wy);
  REQUIRE((Wy + pb.q0 - s.u).norm() <= 1e-10 * (1 + s.u.norm()));
  const ContactResiduals r = residuals(pb, s);
  INFO("pen " << r.penetration << " ten " << r.tension << " comp " << r.complementarity << " coul " << r.coulomb
              << " stick " << r.stick_slip << " dir " << r.slip_direction);
  REQUIRE(r.max() <= 1e-8);
}

}  // namespace rccm::testing

// What an accepted step records of the bulk without solving for its whole displacement: each
// load's resultant and displacement, the probes' displacements and the loads' work pair are
// linear in the condensed state (y, the loads' amplitudes a(t), the interface force r), with
// coefficients condensed once per K0 (Condensation::forms). A step then costs products of the
// interface's size instead of a solve of the body (docs/MODEL.md s7).
#pragma once

#include "rccm/contact/condensation.hpp"
#include "rccm/fem/loads.hpp"
#include "rccm/fem/mesh.hpp"
#include "rccm/interface/interface.hpp"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <vector>

namespace rccm {

/// The loads' work at a state: their amplitudes a_k, phi_k = f_k . u over the free DOFs (what
/// an applied load works on) and rho_k = ud_k . f_ext (the reaction a prescribed displacement
/// works against). Since f_ext = sum_k a_k f_k on the free DOFs and u = sum_k a_k ud_k on the
/// prescribed ones, f_ext(X) . u(Y) = dot(X, Y) = a_X . phi_Y + a_Y . rho_X: bilinear, so the
/// energy balance's quadratures take it as they took the full vectors.
struct LoadWork {
  Eigen::VectorXd a, phi, rho;
};
LoadWork operator+(const LoadWork& x, const LoadWork& y);
LoadWork operator-(const LoadWork& x, const LoadWork& y);
LoadWork operator-(const LoadWork& x);
LoadWork operator*(double c, const LoadWork& x);
LoadWork operator/(const LoadWork& x, double c);
double dot(const LoadWork& x, const LoadWork& y);

/// A step's figures of the bulk, from the forms (BodyForms::evaluate).
struct BodyResultants {
  std::vector<double> force;         // per load: resultant along it, N
  std::vector<double> displacement;  // per load: mean displacement of its nodes along it, mm
  std::vector<double> probes;        // each probe's displacement components, mm
  LoadWork work;
};

class BodyForms {
 public:
  /// `free`: whether each DOF is free (not prescribed); `probes`: mesh nodes.
  BodyForms(const Condensation& condensation, const SparseMatrix& K, const Interface& interface,
            const std::vector<LoadCase>& loads, const std::vector<char>& free, const Mesh& mesh,
            const std::vector<int>& probes);

  /// At time t, with the interface force y = Rbar + E u and r = Rbar + Radh.
  BodyResultants evaluate(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& r) const;

 private:
  static constexpr int per_load = 4;  // columns of load k: phi_k, rho_k, resultant, displacement
  const Condensation& condensation_;
  int loads_ = 0;
  Eigen::VectorXd applied_;  // per load: its own resultant at amplitude 1 (0 for a prescribed displacement)
  Eigen::MatrixXd g_, h_;    // l.u = g.y + h.a (Condensation::forms)
  Eigen::MatrixXd c_;        // and minus c.r: the forms of f_ext = K u - P^T r
};

}  // namespace rccm

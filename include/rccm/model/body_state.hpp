// The bulk at an accepted state: the resultant and displacement of each load, the probes'
// displacements, the loads' work pair and the strain energy; with body_state also the full
// nodal displacement and external forces (applied loads and the reactions at prescribed DOFs).
#pragma once

#include "rccm/model/body_forms.hpp"
#include "rccm/model/interface_state.hpp"
#include "rccm/model/model.hpp"

#include <Eigen/Core>

#include <vector>

namespace rccm {

struct BodyState {
  double t = 0;
  Eigen::VectorXd u;          // full nodal displacement, mm (body_state only)
  Eigen::VectorXd f_ext;      // K u - P^T r: applied forces, and reactions at prescribed DOFs, N (body_state only)
  Eigen::VectorXd r;          // interface force Rbar + Radh (local components per pair), N
  std::vector<double> value;         // per load: prescribed value (mm) or applied amplitude (N, MPa)
  std::vector<double> force;         // per load: resultant of f_ext along it (LoadCase::along), N
  std::vector<double> displacement;  // per load: mean displacement of its nodes along it, mm
  std::vector<double> probes;        // each probe's displacement components, mm
  LoadWork work;                     // f_ext(X) . u(Y) = dot(X.work, Y.work)
  double strain_energy = 0;          // 1/2 u . K u, N mm
};

/// With the full fields: one solve of the body.
BodyState body_state(const Model& model, const InterfaceState& s);
/// The same figures without u and f_ext, from the model's body forms: no solve.
BodyState body_resultants(const Model& model, const InterfaceState& s);

/// Radh = -a beta^2 (Ct u_t, Cn u_n) of every pair at the state s (docs/MODEL.md s3).
Eigen::VectorXd adhesive_forces(const Model& model, const InterfaceState& s);

}  // namespace rccm

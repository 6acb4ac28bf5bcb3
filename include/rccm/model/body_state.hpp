// The bulk at an accepted state: nodal displacement, external forces (applied loads and the
// reactions at prescribed DOFs), and the resultant of each load.
#pragma once

#include "rccm/model/interface_state.hpp"
#include "rccm/model/model.hpp"

#include <Eigen/Core>

#include <vector>

namespace rccm {

struct BodyState {
  double t = 0;
  Eigen::VectorXd u;          // full nodal displacement, mm
  Eigen::VectorXd f_ext;      // K u - P^T r: applied forces, and reactions at prescribed DOFs, N
  Eigen::VectorXd r;          // interface force Rbar + Radh (local components per pair), N
  std::vector<double> value;         // per load: prescribed value (mm) or applied amplitude (N, MPa)
  std::vector<double> force;         // per load: resultant of f_ext along it (LoadCase::along), N
  std::vector<double> displacement;  // per load: mean displacement of its nodes along it, mm
};

BodyState body_state(const Model& model, const InterfaceState& s);

/// Radh = -a beta^2 (Ct u_t, Cn u_n) of every pair at the state s (docs/MODEL.md s3).
Eigen::VectorXd adhesive_forces(const Model& model, const InterfaceState& s);

}  // namespace rccm

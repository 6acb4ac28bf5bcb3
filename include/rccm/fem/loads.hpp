// The loads of a run as unit load cases scaled by amplitudes in time (docs/MODEL.md s1).
#pragma once

#include "rccm/base/config.hpp"
#include "rccm/fem/mesh.hpp"

#include <Eigen/Core>

#include <vector>

namespace rccm {

/// One load: full-size unit nodal forces and unit prescribed values, times amplitude(t).
struct LoadCase {
  TimeFunction amplitude;
  Eigen::VectorXd force;         // N at amplitude 1
  Eigen::VectorXd displacement;  // mm at amplitude 1 (only prescribed DOFs nonzero)
  std::vector<int> prescribed;   // DOFs this load prescribes (a DOF an earlier load holds alike: that load's)
  /// The DOFs it acts on (prescribed or loaded) and the direction it acts along at each:
  /// 1 for a component, the unit inward normal's component for a pressure. Its resultant is
  /// sum along_k f[dofs_k], its displacement sum along_k u[dofs_k] / nodes.
  std::vector<int> dofs;
  std::vector<double> along;
  int nodes = 0;
  bool reaction = false;  // a prescribed displacement: its force is the supports' reaction on its DOFs

  /// sum_k along_k e_{dofs_k} on `ndof` DOFs: its resultant is direction . f, its displacement direction . u / nodes.
  Eigen::VectorXd direction(Eigen::Index ndof) const;
};

/// Turns the config's loads into load cases; throws InputError "file:line: loads.[k]..."
/// for an unknown or empty node set, a DOF prescribed by two loads to different values (to the
/// same values, the first holds it), or a force on a support.
/// `axis`: the DOFs u_r of an axisymmetric mesh's nodes on the axis, held at 0 by the model:
/// a force there, or a radial displacement other than 0, is refused as well.
std::vector<LoadCase> make_load_cases(const Mesh& mesh, const Config& cfg, const std::vector<int>& axis = {});

/// All prescribed DOFs of the load cases.
std::vector<int> prescribed_dofs(const std::vector<LoadCase>& loads);

}  // namespace rccm

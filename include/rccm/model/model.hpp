// Everything a run builds from its config and its mesh: loads, elastic body (K0 factorized
// once, or again when many springs follow beta at once: condense()), interface and condensation. Data
// flows Config + Mesh -> LoadCases -> ElasticProblem -> Interface -> Condensation
// (docs/ARCHITECTURE.md); the model then poses the contact problem at any (t, beta).
#pragma once

#include "rccm/base/config.hpp"
#include "rccm/contact/condensation.hpp"
#include "rccm/contact/contact_problem.hpp"
#include "rccm/fem/elastic_problem.hpp"
#include "rccm/fem/loads.hpp"
#include "rccm/fem/material.hpp"
#include "rccm/fem/mesh.hpp"
#include "rccm/interface/interface.hpp"
#include "rccm/model/body_forms.hpp"

#include <Eigen/Core>

#include <memory>
#include <vector>

namespace rccm {

class Model {
 public:
  /// Builds and checks everything on `mesh` (from a mesh source); throws InputError naming
  /// the config's file, line and setting, before anything is written.
  Model(const Config& cfg, Mesh mesh);
  Model(const Model&) = delete;
  Model& operator=(const Model&) = delete;

  const Mesh& mesh() const { return mesh_; }
  /// The material of each body of the mesh (Mesh::body_names).
  const std::vector<Material>& materials() const { return materials_; }
  const Interface& interface() const { return interface_; }
  /// Doubtful input said before the first step and kept as the run's warnings: the
  /// interface's geometry (Interface::notes), a load table that goes past time.T.
  const std::vector<std::string>& notes() const { return notes_; }
  const Condensation& condensation() const { return *condensation_; }
  /// The bulk's figures at a step without a solve of the body, condensed with K0.
  const BodyForms& body_forms() const { return *forms_; }
  int contact_nodes() const { return interface_.size(); }
  /// Contact node i in a message, findable in the results: "contact node i (mesh node n at
  /// (x, y))". i is the interface's point id in the .vtp and the "node" column of its CSVs;
  /// n the body's point id in the .vtu.
  std::string locate(int i) const;
  /// Who solves the body's K0 (solver.linear): "CHOLMOD", "PETSc MUMPS on 2 processes", ...
  std::string linear_solver() const { return body_->solver_name(); }
  /// The largest extent of the mesh, mm: no small-strain displacement comes near it.
  double size() const { return size_; }

  /// beta0 of every contact pair.
  Eigen::VectorXd initial_beta() const;

  /// Contact pair watched for each output.watch entry (nearest pair to its point).
  const std::vector<int>& watched() const { return watched_; }
  /// Mesh node of each output.probes entry (nearest node to its point).
  const std::vector<int>& probes() const { return probes_; }

  /// The condensed problem at time t and adhesion beta, slip measured from u_ref
  /// (docs/MODEL.md s4). Its W0 points into this model.
  ContactProblem contact_problem(double t, const Eigen::VectorXd& beta, const Eigen::VectorXd& u_ref) const;

  /// The beta of the adhesive springs W0 holds (docs/MODEL.md s4): ones at the start.
  const Eigen::VectorXd& springs_beta() const { return springs_beta_; }
  /// W0 and the load responses with the springs at `beta` (each at least tuning::springs_floor
  /// of D(1)): where they change on a few pairs (tuning::springs_woodbury_fraction), by
  /// Woodbury's formula from the W0 before (Condensation::change_springs); otherwise K0
  /// factorized again with them and everything condensed anew, the body forms too. The contact
  /// problem's solution does not change; its splitting y = Rbar + E u does, and with it the
  /// sweeps' rate: a pair that has lost its adhesion is no longer held in W0 by a spring that E
  /// must take back.
  void condense(const Eigen::VectorXd& beta);
  /// Whether W0's springs lag `beta` enough for condense() to pay (solver.springs_follow_beta):
  /// tuning::springs_lag_fraction of the pairs with a spring weaker than 1 / springs_lag_ratio of W0's.
  bool springs_lag(const Eigen::VectorXd& beta) const;
  /// The springs' beta to condense at when they lag `beta`: beta where a pair's spring weighs
  /// more than tuning::springs_follow_ratio times its weight at beta, springs_beta() elsewhere
  /// (a change on few pairs: condense() by Woodbury's formula).
  Eigen::VectorXd springs_following(const Eigen::VectorXd& beta) const;

  const SparseMatrix& stiffness() const { return K_; }  // bare K, all DOFs
  const std::vector<LoadCase>& loads() const { return loads_; }
  /// The DOFs held: prescribed by the loads, and u_r on the axis of an axisymmetric mesh.
  const std::vector<int>& supports() const { return supports_; }
  /// Whether each DOF is free: not among supports().
  const std::vector<char>& free_dofs() const { return free_; }

 private:
  /// Throws InputError when no contact state can hold the body (a frictionless, unbonded interface).
  void check_restrained(const Config& cfg) const;
  /// Throws InputError when a prescribed displacement presses a contact node into the foundation.
  void check_prescribed_gaps(const Config& cfg) const;
  /// A load table with points past time.T (given in ms, or a long table run short): noted.
  void note_tables_past_T(const Config& cfg);

  Mesh mesh_;
  std::vector<Material> materials_;
  double size_ = 0;
  Interface interface_;
  std::vector<std::string> notes_;
  std::vector<LoadCase> loads_;
  std::vector<int> supports_;
  std::vector<char> free_;
  SparseMatrix K_;
  std::unique_ptr<ElasticProblem> body_;
  std::unique_ptr<Condensation> condensation_;
  std::unique_ptr<BodyForms> forms_;
  bool follow_beta_ = false, compress_W0_ = false;
  LinearSolverParams linear_;
  std::vector<int> interface_dofs_;  // ordered last in K0's factor (dense W0), or K0^-1's entries on them (MUMPS)
  Eigen::VectorXd springs_beta_;
  Eigen::VectorXd D1_, Dref_, g0_;   // the springs at beta = 1 and those in W0
  std::vector<int> watched_, probes_;
};

}  // namespace rccm

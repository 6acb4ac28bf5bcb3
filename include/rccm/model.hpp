// Everything a run builds once from its config: mesh, loads, elastic body (K0 factorized),
// interface and condensation. Data flows Config -> Mesh -> ElasticProblem -> Interface ->
// Condensation (docs/STYLE.md); the model then poses the contact problem at any (t, beta).
#pragma once

#include "rccm/condensation.hpp"
#include "rccm/config.hpp"
#include "rccm/contact_problem.hpp"
#include "rccm/elastic_problem.hpp"
#include "rccm/interface.hpp"
#include "rccm/loads.hpp"
#include "rccm/mesh.hpp"

#include <Eigen/Core>

#include <memory>
#include <vector>

namespace rccm {

class Model {
 public:
  /// Builds and checks everything; throws InputError before anything is written.
  explicit Model(const Config& cfg);
  Model(const Model&) = delete;
  Model& operator=(const Model&) = delete;

  const Config& config() const { return cfg_; }
  const Mesh& mesh() const { return mesh_; }
  const Interface& interface() const { return interface_; }
  const Condensation& condensation() const { return *condensation_; }
  int contact_nodes() const { return interface_.size(); }

  /// beta0 of the config, one per contact node.
  Eigen::VectorXd initial_beta() const;

  /// Contact node watched for each output.watch entry (nearest node to its point).
  const std::vector<int>& watched() const { return watched_; }

  /// The condensed problem at time t and adhesion beta, slip measured from ut_ref
  /// (MODEL.md s4). Its W0 points into this model.
  ContactProblem contact_problem(double t, const Eigen::VectorXd& beta, const Eigen::VectorXd& ut_ref) const;

  const SparseMatrix& stiffness() const { return K_; }  // bare K, all DOFs
  const std::vector<LoadCase>& loads() const { return loads_; }

 private:
  /// Throws InputError when no contact state can hold the body (a frictionless, unbonded interface).
  void check_restrained(const Config& cfg, const Eigen::VectorXd& beta0) const;

  Config cfg_;
  Mesh mesh_;
  Interface interface_;
  std::vector<LoadCase> loads_;
  SparseMatrix K_;
  std::unique_ptr<ElasticProblem> body_;
  std::unique_ptr<Condensation> condensation_;
  Eigen::VectorXd D1_, g0_;
  std::vector<int> watched_;
};

}  // namespace rccm

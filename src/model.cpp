#include "rccm/model.hpp"

#include "rccm/errors.hpp"

#include <sstream>

namespace rccm {

namespace {

std::vector<int> find_watched(const Config& cfg, const Mesh& mesh, const Interface& I) {
  std::vector<int> out;
  const double reach = 1e-6 * std::max(cfg.mesh.size[0], cfg.mesh.size[1]) + I.a.maxCoeff();
  for (std::size_t k = 0; k < cfg.output.watch.size(); ++k) {
    const WatchPoint& w = cfg.output.watch[k];
    const Eigen::Vector2d p = placed(cfg.mesh, {w.point[0], w.point[1]});
    int best = 0;
    for (int i = 1; i < I.size(); ++i)
      if ((mesh.nodes[I.nodes[i]] - p).norm() < (mesh.nodes[I.nodes[best]] - p).norm()) best = i;
    const double d = (mesh.nodes[I.nodes[best]] - p).norm();
    if (d > reach) {
      std::ostringstream m;
      m << cfg.where("output.watch.[" + std::to_string(k) + "]") << " '" << w.name << "': point (" << p.x() << ", " << p.y()
        << ") is " << d << " mm from the nearest contact node; give a point on the interface";
      throw InputError(m.str());
    }
    out.push_back(best);
  }
  return out;
}

/// One value per contact node from a config list of one value or one per node.
Eigen::VectorXd per_node(const std::vector<double>& v, int n) {
  if (v.size() == 1) return Eigen::VectorXd::Constant(n, v[0]);
  return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
}

void check_per_node(const Config& cfg, const char* setting, const std::vector<double>& v, int n) {
  if (v.size() != 1 && static_cast<int>(v.size()) != n)
    throw InputError(cfg.where(std::string("interface.") + setting) + ": give one value or one per contact node (" +
                     std::to_string(n) + "), got " + std::to_string(v.size()));
}

}  // namespace

Model::Model(const Config& cfg) : cfg_(cfg), mesh_(make_rectangle(cfg.mesh)) {
  try {
    interface_ = make_interface(mesh_, cfg.interface);
  } catch (const InputError& e) {
    throw InputError(cfg.where("interface.boundary") + ": " + e.what());
  }
  check_per_node(cfg, "beta0", cfg.interface.beta0, interface_.size());
  check_per_node(cfg, "g0", cfg.interface.g0, interface_.size());
  g0_ = per_node(cfg.interface.g0, interface_.size());
  loads_ = make_load_cases(mesh_, cfg);
  K_ = assemble_stiffness(mesh_, cfg.material);
  check_restrained(cfg, initial_beta());
  std::vector<int> interface_dofs;
  for (int node : interface_.nodes) interface_dofs.insert(interface_dofs.end(), {2 * node, 2 * node + 1});
  try {
    body_ = std::make_unique<ElasticProblem>(K_, interface_.initial_springs(), prescribed_dofs(loads_), interface_dofs);
  } catch (const InputError& e) {  // a singular stiffness: the loads' supports and the interface do not hold the body
    throw InputError(cfg.where("loads") + ": " + e.what());
  }
  condensation_ = std::make_unique<Condensation>(*body_, interface_, loads_);
  D1_.resize(2 * interface_.size());
  for (int i = 0; i < interface_.size(); ++i)
    D1_.segment<2>(2 * i) << interface_.a[i] * interface_.Ct, interface_.a[i] * interface_.Cn;
  watched_ = find_watched(cfg, mesh_, interface_);
}

void Model::check_restrained(const Config& cfg, const Eigen::VectorXd& beta0) const {
  // With friction or adhesion at every node, any contact state holds the interface in both
  // directions. Without (mu = 0 and beta0 = 0 somewhere), contact can only push: the body
  // must be held with the normal direction of every node bonded and the tangential one only
  // where beta0 > 0; if not even that holds it, no contact state does.
  if (cfg.interface.mu > 0 || (beta0.array() > 0).all()) return;
  const Eigen::VectorXd tangential = beta0.cwiseProduct(beta0), normal = Eigen::VectorXd::Ones(beta0.size());
  try {
    ElasticProblem(K_, interface_.springs(tangential, normal), prescribed_dofs(loads_));
  } catch (const InputError&) {
    throw InputError(cfg.where("interface.mu") + ": the body is not restrained: with mu = 0 and beta0 = 0 the "
                     "interface is frictionless and unbonded, and nothing holds the body tangentially; give mu > 0 "
                     "or beta0 > 0, or prescribe a displacement");
  }
}

Eigen::VectorXd Model::initial_beta() const { return per_node(cfg_.interface.beta0, interface_.size()); }

ContactProblem Model::contact_problem(double t, const Eigen::VectorXd& beta, const Eigen::VectorXd& ut_ref) const {
  ContactProblem pb;
  pb.W0 = &condensation_->W0();
  pb.q0 = condensation_->q0(t);
  pb.D1 = D1_;
  pb.Dbeta.resize(D1_.size());
  for (int i = 0; i < interface_.size(); ++i)
    pb.Dbeta.segment<2>(2 * i) = beta[i] * beta[i] * D1_.segment<2>(2 * i);  // MODEL.md s4, D(beta)
  pb.mubar = cfg_.interface.mu * (1.0 - beta.array());                     // paper eq. 20
  pb.g0 = g0_;
  pb.ut_ref = ut_ref;
  return pb;
}

}  // namespace rccm

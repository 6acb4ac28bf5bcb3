#include "rccm/model/model.hpp"

#include "rccm/base/errors.hpp"
#include "rccm/fem/elasticity.hpp"

#include <sstream>

namespace rccm {

namespace {

double extent(const Mesh& mesh) {
  Eigen::Vector3d lo = mesh.nodes.front(), hi = lo;
  for (const Eigen::Vector3d& x : mesh.nodes) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
  return (hi - lo).maxCoeff();
}

std::vector<int> find_watched(const Config& cfg, const Mesh& mesh, const Interface& I, double size) {
  std::vector<int> out;
  double a_max = 0;
  for (const ContactPair& c : I.pairs) a_max = std::max(a_max, c.measure);
  const double reach = 1e-6 * size + a_max;
  for (std::size_t k = 0; k < cfg.output.watch.size(); ++k) {
    const WatchPoint& w = cfg.output.watch[k];
    const Eigen::Vector3d p = mesh.placement(Eigen::Vector3d(w.point[0], w.point[1], 0.0));
    const auto distance = [&](int i) { return (mesh.nodes[I.pairs[i].node] - p).norm(); };
    int best = 0;
    for (int i = 1; i < I.size(); ++i)
      if (distance(i) < distance(best)) best = i;
    if (distance(best) > reach) {
      std::ostringstream m;
      m << cfg.where("output.watch.[" + std::to_string(k) + "]") << " '" << w.name << "': point (" << p.x() << ", "
        << p.y() << ") is " << distance(best) << " mm from the nearest contact node; give a point on the interface";
      throw InputError(m.str());
    }
    out.push_back(best);
  }
  return out;
}

}  // namespace

Model::Model(const Config& cfg, Mesh mesh)
    : mesh_(std::move(mesh)), material_(cfg.material), size_(extent(mesh_)), interface_(make_interface(mesh_, cfg)) {
  loads_ = make_load_cases(mesh_, cfg);
  K_ = assemble_stiffness(mesh_, cfg.material);
  check_restrained(cfg);
  std::vector<int> interface_dofs;
  for (const ContactPair& c : interface_.pairs)
    for (int node : {c.node, c.opposite})
      for (int x = 0; node >= 0 && x < mesh_.dim; ++x) interface_dofs.push_back(mesh_.dof(node, x));
  try {
    body_ = std::make_unique<ElasticProblem>(K_, interface_.initial_springs(), prescribed_dofs(loads_), interface_dofs);
  } catch (const InputError& e) {  // a singular stiffness: the loads' supports and the interface do not hold the body
    throw InputError(cfg.where("loads") + ": " + e.what());
  }
  condensation_ = std::make_unique<Condensation>(*body_, interface_, loads_);
  D1_ = interface_.spring_stiffness();
  g0_.resize(interface_.size());
  for (int i = 0; i < interface_.size(); ++i) g0_[i] = interface_.pairs[i].g0;
  watched_ = find_watched(cfg, mesh_, interface_, size_);
}

void Model::check_restrained(const Config& cfg) const {
  // With friction or adhesion at every pair, any contact state holds the interface in both
  // directions. Without (mu = 0 and beta0 = 0 somewhere), contact can only push: the body
  // must be held with the normal direction of every pair bonded and the tangential one only
  // where beta0 > 0; if not even that holds it, no contact state does.
  const Eigen::VectorXd beta0 = initial_beta();
  int loose = -1;
  for (int i = 0; i < interface_.size() && loose < 0; ++i)
    if (interface_.law(i).mu == 0 && beta0[i] == 0) loose = i;
  if (loose < 0) return;
  const Eigen::VectorXd tangential = beta0.cwiseProduct(beta0), normal = Eigen::VectorXd::Ones(beta0.size());
  try {
    ElasticProblem(K_, interface_.springs(tangential, normal), prescribed_dofs(loads_));
  } catch (const InputError&) {
    throw InputError(cfg.where(cfg.interfaces[interface_.pairs[loose].law].path + ".mu") +
                     ": the body is not restrained: with mu = 0 and beta0 = 0 the interface is frictionless and "
                     "unbonded, and nothing holds the body tangentially; give mu > 0 or beta0 > 0, or prescribe a "
                     "displacement");
  }
}

Eigen::VectorXd Model::initial_beta() const {
  Eigen::VectorXd beta(interface_.size());
  for (int i = 0; i < interface_.size(); ++i) beta[i] = interface_.pairs[i].beta0;
  return beta;
}

ContactProblem Model::contact_problem(double t, const Eigen::VectorXd& beta, const Eigen::VectorXd& u_ref) const {
  const Layout& L = interface_.layout;
  ContactProblem pb;
  pb.layout = L;
  pb.W0 = &condensation_->W0();
  pb.q0 = condensation_->q0(t);
  pb.D1 = D1_;
  pb.Dbeta.resize(D1_.size());
  pb.mubar.resize(interface_.size());
  for (int i = 0; i < interface_.size(); ++i) {
    const double beta2 = beta[i] * beta[i];
    for (Eigen::Index c = L.offset(i); c <= L.normal(i); ++c) pb.Dbeta[c] = beta2 * D1_[c];  // docs/MODEL.md s4, D(beta)
    pb.mubar[i] = interface_.law(i).mubar(beta[i]);                                      // paper eq. 20
  }
  pb.g0 = g0_;
  pb.u_ref = u_ref;
  return pb;
}

}  // namespace rccm

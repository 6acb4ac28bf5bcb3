#include "rccm/model/model.hpp"

#include "rccm/base/errors.hpp"
#include "rccm/base/memory.hpp"
#include "rccm/base/suggest.hpp"
#include "rccm/contact/solver_tuning.hpp"
#include "rccm/fem/elasticity.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace rccm {

namespace {

double extent(const Mesh& mesh) {
  Eigen::Vector3d lo = mesh.nodes.front(), hi = lo;
  for (const Eigen::Vector3d& x : mesh.nodes) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
  return (hi - lo).maxCoeff();
}

/// For each named point of output.<list>, the nearest of `candidates` (mesh nodes); refused
/// when it lies farther than `reach` from all of them.
std::vector<int> nearest(const Config& cfg, const Mesh& mesh, const std::vector<NamedPoint>& points,
                         const std::string& list, const std::vector<int>& candidates, double reach, const char* what) {
  std::vector<int> out;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Eigen::Vector3d given(points[k].point[0], points[k].point[1], points[k].point[2]);  // in the unturned frame
    const Eigen::Vector3d p = mesh.placement(given);
    const auto distance = [&](std::size_t j) { return (mesh.nodes[candidates[j]] - p).norm(); };
    std::size_t best = 0;
    for (std::size_t j = 1; j < candidates.size(); ++j)
      if (distance(j) < distance(best)) best = j;
    if (distance(best) > reach) {
      std::ostringstream m;
      m << cfg.where("output." + list + ".[" + std::to_string(k) + "]") << " '" << points[k].name << "': point "
        << point(given, mesh.dim) << (p == given ? "" : " (" + point(p, mesh.dim) + " once the mesh is placed)") << " is "
        << distance(best) << " mm from the nearest " << what;
      throw InputError(m.str());
    }
    // Two nodes at that point (two bodies glued there, or the two sides of a crack in one body,
    // each with its own nodes): the node of the body, then of the cells, the point lies in; on
    // the boundary or the crack they share, which one it means is the user's to say.
    std::vector<std::size_t> shared{best};
    for (std::size_t j = 0; j < candidates.size(); ++j)
      if (j != best && (mesh.nodes[candidates[j]] - mesh.nodes[candidates[best]]).norm() <= 1e-9 * reach) shared.push_back(j);
    if (shared.size() > 1) {
      const auto in_cell = [&](int node, int c) {
        return std::find(mesh.cells[c].begin(), mesh.cells[c].end(), node) != mesh.cells[c].end();
      };
      const auto in_body = [&](int node, int body) {  // a node of a cell of `body` (bodies without an interface share nodes)
        for (std::size_t c = 0; c < mesh.cells.size(); ++c)
          if (mesh.cell_body[c] == body && in_cell(node, int(c))) return true;
        return false;
      };
      const auto body_of = [&](int node) {  // cells are listed body by body: the first body of the node
        for (std::size_t c = 0; c < mesh.cells.size(); ++c)
          if (in_cell(node, int(c))) return mesh.cell_body[c];
        return -1;
      };
      const std::vector<int> holding = mesh.bodies_holding(p);
      std::vector<std::size_t> in;  // the shared nodes of the body the point lies in
      for (std::size_t j : shared)
        if (holding.size() == 1 && in_body(candidates[j], holding[0])) in.push_back(j);
      const bool crack = in.size() > 1;
      if (crack) {  // of those, the nodes of the cells that hold the point
        const std::vector<int> cells = mesh.cells_holding(p);
        in.erase(std::remove_if(in.begin(), in.end(), [&](std::size_t j) {
                   return std::none_of(cells.begin(), cells.end(), [&](int c) { return in_cell(candidates[j], c); });
                 }), in.end());
      }
      if (in.size() != 1) {
        const auto name = [&](std::size_t j) {
          const int b = body_of(candidates[j]);
          return b < 0 ? std::string("no body") : "body '" + mesh.body_names[b] + "'";
        };
        std::ostringstream m;
        m << cfg.where("output." + list + ".[" + std::to_string(k) + "]") << " '" << points[k].name << "': point "
          << point(given, mesh.dim) << " is as near to mesh node " << candidates[shared[0]] << " of " << name(shared[0])
          << " as to mesh node " << candidates[shared[1]] << " of " << name(shared[1]) << " (they share that point), and lies "
          << (holding.empty() ? "in no body"
              : holding.size() > 1 ? "on the boundary they share"
              : crack ? (in.empty() ? "in a cell with neither as a corner"
                                    : "on the crack between them, in body '" + mesh.body_names[holding[0]] + "'")
              : "in body '" + mesh.body_names[holding[0]] + "'")
          << (crack && in.empty() ? "; move it nearer the node you mean" : "; move it into the body, or the side of the crack, you mean");
        throw InputError(m.str());
      }
      best = in[0];
    }
    out.push_back(static_cast<int>(best));
  }
  return out;
}

/// The material of each body of the mesh, from the config's `material` (every body) or
/// `bodies` (by name, each body once).
std::vector<Material> body_materials(const Config& cfg, const Mesh& mesh) {
  if (cfg.bodies.size() == 1 && cfg.bodies[0].name.empty())
    return std::vector<Material>(mesh.body_names.size(), Material(cfg.bodies[0].material));
  // A name the mesh does not know first: a misspelt body is also one without a material.
  for (std::size_t k = 0; k < cfg.bodies.size(); ++k)
    if (std::find(mesh.body_names.begin(), mesh.body_names.end(), cfg.bodies[k].name) == mesh.body_names.end())
      throw InputError(cfg.where("bodies.[" + std::to_string(k) + "].name") + ": the mesh has no body named '" +
                       cfg.bodies[k].name + "'" + suggestion(cfg.bodies[k].name, mesh.body_names));
  std::vector<Material> out;
  for (const std::string& name : mesh.body_names) {
    const auto it = std::find_if(cfg.bodies.begin(), cfg.bodies.end(), [&](const BodyParams& b) { return b.name == name; });
    if (it == cfg.bodies.end())
      throw InputError(cfg.where("bodies") + ": the mesh's body '" + name + "' has no material: add { name = \"" + name +
                       "\"; material = { ... }; } to bodies");
    out.emplace_back(it->material);
  }
  return out;
}

/// An axisymmetric mesh lies in r = x >= 0 and holds u_r = 0 on the axis.
std::vector<int> axis_supports(const Config& cfg, const Mesh& mesh, double size) {
  std::vector<int> dofs;
  if (!mesh.axisymmetric) return dofs;
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    const double r = mesh.nodes[n].x();
    if (r < -1e-9 * size) {
      std::ostringstream m;
      m << cfg.where(cfg.bodies.front().material.path + ".hypothesis") << ": an axisymmetric mesh lies in x = r >= 0; node "
        << n << " lies at r = " << r;
      throw InputError(m.str());
    }
    if (r <= 1e-9 * size) dofs.push_back(mesh.dof(n, 0));
  }
  return dofs;
}

/// The largest distance between two nodes of a cell.
double largest_cell(const Mesh& mesh) {
  double h = 0;
  for (const auto& cell : mesh.cells)
    for (int a : cell)
      for (int b : cell) h = std::max(h, (mesh.nodes[a] - mesh.nodes[b]).norm());
  return h;
}

}  // namespace

Model::Model(const Config& cfg, Mesh mesh)
    : mesh_(std::move(mesh)), size_(extent(mesh_)) {
  for (const Eigen::Vector3d& x : mesh_.nodes)
    if (!x.allFinite()) throw InputError(cfg.file + ": mesh: node coordinates overflow (the mesh is too large)");
  mesh_.axisymmetric = cfg.hypothesis() == Hypothesis::Axisymmetric;
  materials_ = body_materials(cfg, mesh_);
  interface_ = make_interface(mesh_, cfg);
  // W0 compressed from sparse solves on large interfaces, where the solver can use it (rccm
  // and the 3D Newton step read W0 dense); otherwise dense, with the factor block it comes from,
  // and below solver.compressed_min_nodes the exact step's matrix, its LU and its inverse,
  // each (dim m)^2 doubles.
  compress_W0_ = interface_.size() >= cfg.solver.compressed_min_nodes && cfg.solver.reads_compressed_W0();
  const double m = interface_.layout.offset(interface_.size());
  // Three more (dim m)^2 matrices beside W0 and its factor block: the exact step's (the
  // bipotential solver's when it takes the step, 2D Newton's always) or rccm's inverse of W0
  // with its factorization.
  const bool exact = (cfg.solver.method == ContactMethod::Bipotential && cfg.solver.active_set &&
                      interface_.size() <= cfg.solver.active_set_max_nodes) ||
                     (cfg.solver.method == ContactMethod::Newton && interface_.layout.dim == 2) ||
                     cfg.solver.method == ContactMethod::Rccm;
  if (!compress_W0_)
    require_memory((exact ? 5 : 2) * 8 * m * m, cfg.where(cfg.interfaces.front().path + ".boundary"),
                   std::to_string(interface_.size()) + " contact nodes (dense interface operators)",
                   "use a coarser interface mesh, solver.compressed_min_nodes below the contact node count, or "
                   "solver.active_set_max_nodes below it");
  const std::vector<int> axis = axis_supports(cfg, mesh_, size_);
  loads_ = make_load_cases(mesh_, cfg, axis);
  supports_ = prescribed_dofs(loads_);
  supports_.insert(supports_.end(), axis.begin(), axis.end());
  free_.assign(mesh_.num_dofs(), 1);
  for (int d : supports_) free_[d] = 0;
  if (supports_.size() == static_cast<std::size_t>(mesh_.num_dofs()))
    throw InputError(cfg.where("loads") + ": every degree of freedom is prescribed: nothing is left to solve");
  check_prescribed_gaps(cfg);
  notes_ = interface_.notes;
  note_tables_past_T(cfg);
  K_ = assemble_stiffness(mesh_, materials_);
  check_restrained(cfg);
  follow_beta_ = cfg.solver.springs_follow_beta;
  linear_ = cfg.solver.linear;
  // The interface's DOFs: ordered last by CHOLMOD for a dense W0; MUMPS computes K0^-1's
  // entries on them (one process), so that a compressed W0's products need no solve of the body.
  if (!compress_W0_ || chosen_linear_solver(linear_.kind) == LinearSolver::Mumps)
    for (const ContactPair& c : interface_.pairs)
      for (int node : {c.node, c.opposite})
        for (int x = 0; node >= 0 && x < mesh_.dim; ++x) interface_dofs_.push_back(mesh_.dof(node, x));
  D1_ = interface_.spring_stiffness();
  g0_.resize(interface_.size());
  for (int i = 0; i < interface_.size(); ++i) g0_[i] = interface_.pairs[i].g0;
  double a_max = 0;
  std::vector<int> contact_nodes, all_nodes(mesh_.num_nodes());
  for (const ContactPair& c : interface_.pairs) a_max = std::max(a_max, c.measure), contact_nodes.push_back(c.node);
  for (int n = 0; n < mesh_.num_nodes(); ++n) all_nodes[n] = n;
  watched_ = nearest(cfg, mesh_, cfg.output.watch, "watch", contact_nodes, 1e-6 * size_ + a_max,
                     "contact node; give a point on the interface");
  probes_ = nearest(cfg, mesh_, cfg.output.probes, "probes", all_nodes, largest_cell(mesh_),
                    "node, more than a cell; give a point in a body");
  try {
    condense(Eigen::VectorXd::Ones(interface_.size()));  // the springs at beta = 1
  } catch (const MemoryShortfall& e) {  // the factor's size, known once its ordering is
    throw InputError(cfg.where("mesh") + ": " + e.what() +
                     "; use fewer cells (in 3D a factor grows faster than the unknowns), solver.linear = \"cg-gamg\" "
                     "(no factor), \"mumps\" with solver.out_of_core = true (its factor on disk, in "
                     "MUMPS_OOC_TMPDIR or /tmp), or share the factor among processes under mpirun (\"mumps\")");
  } catch (const InputError& e) {  // a singular stiffness: the loads' supports and the interface do not hold the body
    throw InputError(cfg.where("loads") + ": " + e.what());
  }
}

namespace {
/// The weight of a pair's springs in K0 when they are set at beta: beta^2, at least the floor.
double springs_weight(double beta) { return std::max(beta * beta, tuning::springs_floor); }
}  // namespace

void Model::condense(const Eigen::VectorXd& beta) {
  RCCM_VERIFY(beta.size() == interface_.size(), "one beta per contact pair");
  const Eigen::VectorXd w = beta.unaryExpr(&springs_weight);
  const Layout& L = interface_.layout;
  Eigen::VectorXd Dref = D1_;
  for (int i = 0; i < interface_.size(); ++i) L.local(Dref, i) *= w[i];
  Eigen::Index changed = 0;
  for (Eigen::Index c = 0; c < Dref.size() && condensation_; ++c) changed += Dref[c] != Dref_[c];
  if (condensation_ && changed <= tuning::springs_woodbury_fraction * Dref.size()) {
    condensation_->change_springs(Dref_ - Dref);  // a few pairs: K0 and the body forms stay
  } else {
    forms_.reset();  // each refers to the one before it replaces (and all to the memory of the new ones)
    condensation_.reset();
    body_.reset();
    body_ = std::make_unique<ElasticProblem>(K_, interface_.springs(w, w), supports_, interface_dofs_, linear_);
    condensation_ = std::make_unique<Condensation>(*body_, interface_, loads_, compress_W0_);
    forms_ = std::make_unique<BodyForms>(*condensation_, K_, interface_, loads_, free_, mesh_, probes_);
  }
  springs_beta_ = beta;
  Dref_ = Dref;
}

Eigen::VectorXd Model::springs_following(const Eigen::VectorXd& beta) const {
  Eigen::VectorXd out = springs_beta_;
  for (int i = 0; i < interface_.size(); ++i)
    if (springs_weight(beta[i]) * tuning::springs_follow_ratio < springs_weight(springs_beta_[i])) out[i] = beta[i];
  return out;
}

bool Model::springs_lag(const Eigen::VectorXd& beta) const {
  if (!follow_beta_) return false;
  int lagging = 0;
  for (int i = 0; i < interface_.size(); ++i)
    lagging += springs_weight(beta[i]) * tuning::springs_lag_ratio < springs_weight(springs_beta_[i]);
  return lagging > 0 && lagging >= tuning::springs_lag_fraction * interface_.size();
}

void Model::note_tables_past_T(const Config& cfg) {
  for (const LoadParams& p : cfg.loads) {
    const TimeFunction& f = p.amplitude;
    if (f.t.size() < 2 || f.t.back() <= cfg.time.T * (1 + 1e-12)) continue;  // a ramp (value) ends at T
    std::ostringstream m;
    m << cfg.where(p.path + ".table") << ": its times go to " << f.t.back() << " s, past time.T = " << cfg.time.T
      << " s: the run applies it up to T only (" << f(cfg.time.T) << " at T, " << f.v.back()
      << " at its end); times are in s";
    notes_.push_back(m.str());
  }
}

void Model::check_prescribed_gaps(const Config& cfg) const {
  // A contact pair whose relative displacement along its normal (u_node - u_opposite, the
  // opposite node fixed for a rigid foundation) is prescribed has its gap fixed by the loads:
  // a prescribed closing beyond g0 would press it into the foundation or the other body (with
  // an unbounded contact force). Loads are piecewise linear: checked at their breakpoints.
  std::vector<double> times = {0.0, cfg.time.T};
  for (const LoadCase& lc : loads_)
    for (double t : lc.amplitude.t)
      if (t > 0 && t < cfg.time.T) times.push_back(t);
  std::sort(times.begin(), times.end());  // the first time the loads press in is the one to name
  std::vector<char> prescribed(mesh_.num_dofs(), 0);
  for (int d : supports_) prescribed[d] = 1;
  // A component of the unit normal this small (an axis-aligned normal given or computed with
  // round-off, [1e-13, 1]) moves nothing along the normal: its displacement need not be prescribed.
  constexpr double along_normal = 1e-9;
  for (int i = 0; i < interface_.size(); ++i) {
    const ContactPair& c = interface_.pairs[i];
    bool fixed = true;
    for (int x = 0; x < mesh_.dim; ++x)
      fixed = fixed && (std::abs(c.frame.n[x]) <= along_normal || (prescribed[mesh_.dof(c.node, x)] &&
                                              (c.opposite < 0 || prescribed[mesh_.dof(c.opposite, x)])));
    if (!fixed) continue;
    for (double t : times) {
      double u_n = 0;
      for (const LoadCase& lc : loads_)
        for (int x = 0; x < mesh_.dim; ++x) {
          const double opposite = c.opposite < 0 ? 0.0 : lc.displacement[mesh_.dof(c.opposite, x)];
          u_n += c.frame.n[x] * lc.amplitude(t) * (lc.displacement[mesh_.dof(c.node, x)] - opposite);
        }
      if (c.g0 + u_n < -1e-9 * size_) {
        std::ostringstream m;
        m << cfg.where("loads") << ": the prescribed displacements push contact node " << i << " "
          << point(mesh_.nodes[c.node], mesh_.dim) << " into "
          << (c.opposite < 0 ? "the foundation" : "the other body (its mesh node " + std::to_string(c.opposite) + ")")
          << " by " << -(c.g0 + u_n)
          << " mm at t = " << t << " s; a node on the interface may be moved away from the other side (or along "
          << "it), not into it";
        throw InputError(m.str());
      }
    }
  }
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
    ElasticProblem(K_, interface_.springs(tangential, normal), supports_, {}, cfg.solver.linear);
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

std::string Model::locate(int i) const {
  if (i < 0 || i >= interface_.size()) return "contact node " + std::to_string(i);  // never fail while reporting
  const int n = interface_.pairs[i].node;
  return "contact node " + std::to_string(i) + " (mesh node " + std::to_string(n) + " at " +
         point(mesh_.nodes[n], mesh_.dim) + ")";
}

ContactProblem Model::contact_problem(double t, const Eigen::VectorXd& beta, const Eigen::VectorXd& u_ref) const {
  const Layout& L = interface_.layout;
  ContactProblem pb;
  pb.layout = L;
  pb.W0 = &condensation_->W0();
  pb.q0 = condensation_->q0(t);
  pb.Dref = Dref_;
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

#include "rccm/base/config.hpp"

#include "rccm/base/format.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>

namespace rccm {

namespace {

/// The setting a user writes for a hashed value, where its name in the hash is another.
std::string written_as(const std::string& name) {
  static const std::map<std::string, std::string> written{
      {"mesh.axis", "mesh.rotation"},          {"mesh.node_sets.name", "mesh.node_sets"},
      {"mesh.node_sets.box", "mesh.node_sets"}, {"body.name", "bodies.name"},
      {"material.orthotropic", "material"},    {"interface.facing", "interface.normal"},
      {"interface.centre", "interface.circle"}, {"interface.axis", "interface.circle"},
      {"interface.radius", "interface.circle"}, {"interface.inside", "interface.circle"},
      {"loads.kind", "loads.type"},            {"loads.t", "loads.value"},
      {"loads.v", "loads.value"},              {"output.watch.name", "output.watch"},
      {"output.watch.point", "output.watch"},  {"output.probes.name", "output.probes"},
      {"output.probes.point", "output.probes"}};
  const auto it = written.find(name);
  return it == written.end() ? name : it->second;
}

/// FNV-1a of named values written exactly (doubles as hex floats), and one of each name's
/// values alone (parts(): what a refused restart names).
class Hash {
 public:
  Hash& operator()(const char* name, double v) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%s=%a;", name, v);
    return mix(name, buf);
  }
  Hash& operator()(const char* name, const std::string& v) { return mix(name, std::string(name) + "=" + v + ";"); }
  template <class Numbers>
  Hash& list(const char* name, const Numbers& v) {
    (*this)(name, double(v.size()));
    for (double x : v) (*this)(name, x);
    return *this;
  }
  std::string hex() const {
    char out[20];
    std::snprintf(out, sizeof out, "%016llx", static_cast<unsigned long long>(h_));
    return out;
  }
  /// "name=digest name=digest ...", by name; 32 bits a name (the whole hash decides, these name).
  std::string parts() const {
    std::string out;
    for (const auto& [name, h] : parts_) {
      char digest[12];
      std::snprintf(digest, sizeof digest, "%08llx", static_cast<unsigned long long>(h >> 32));
      out += (out.empty() ? "" : " ") + name + "=" + digest;
    }
    return out;
  }

 private:
  Hash& mix(const std::string& name, const std::string& text) {
    auto part = parts_.try_emplace(written_as(name), basis).first;
    for (unsigned char ch : text) {
      h_ = (h_ ^ ch) * prime;
      part->second = (part->second ^ ch) * prime;
    }
    return *this;
  }
  static constexpr std::uint64_t basis = 14695981039346656037ull, prime = 1099511628211ull;
  std::uint64_t h_ = basis;
  std::map<std::string, std::uint64_t> parts_;
};

/// Every value that defines the problem and its time grid (Config::fingerprint).
Hash hash_settings(const Config& c) {
  const MeshParams& mesh = c.mesh;
  Hash h;
  h("mesh.file", mesh.contents)("mesh.refine", mesh.refine);
  for (const auto& [name, value] : mesh.parameters) h(("mesh.parameters." + name).c_str(), value);
  // The origin's z and the turn's axis counted where they are not the defaults: the
  // checkpoints of meshes without them (every 2D one) stay valid.
  const std::array<double, 2> origin_xy{mesh.origin[0], mesh.origin[1]};
  if (mesh.origin[2] != 0.0 || mesh.axis != std::array<double, 3>{0.0, 0.0, 1.0})
    h.list("mesh.origin", mesh.origin).list("mesh.axis", mesh.axis);
  else
    h.list("mesh.origin", origin_xy);
  h.list("mesh.size", mesh.size)("mesh.nx", mesh.nx)("mesh.ny", mesh.ny);
  h("mesh.depth", mesh.depth)("mesh.nz", mesh.nz)("mesh.element", double(mesh.element))("mesh.rotation", mesh.rotation);
  for (const NodeSetDef& d : mesh.node_sets) h("mesh.node_sets.name", d.name).list("mesh.node_sets.box", d.box);
  for (const BodyParams& b : c.bodies) {
    const MaterialParams& m = b.material;
    h("body.name", b.name)("material.orthotropic", m.orthotropic)("material.E", m.E)("material.nu", m.nu);
    h("material.E1", m.E1)("material.E2", m.E2)("material.E3", m.E3)("material.nu12", m.nu12)("material.nu13", m.nu13);
    h("material.nu23", m.nu23)("material.G12", m.G12)("material.G13", m.G13)("material.G23", m.G23)("material.angle", m.angle)("material.hypothesis", double(m.hypothesis));
    h.list("material.axis3", m.axis3);
  }
  for (const InterfaceParams& p : c.interfaces) {
    h("interface.boundary", p.boundary)("interface.facing", double(p.facing)).list("interface.normal", p.normal);
    h.list("interface.centre", p.centre).list("interface.axis", p.axis)("interface.radius", p.radius)("interface.inside", p.inside);
    h("interface.opposite", p.opposite)("interface.tolerance", p.tolerance)("interface.precrack", p.precrack);
    h("interface.Cn", p.Cn)("interface.Ct", p.Ct);
    h("interface.w", p.w)("interface.alpha", p.alpha)("interface.mu", p.mu);
    h.list("interface.beta0", p.beta0).list("interface.g0", p.g0);
  }
  for (const LoadParams& l : c.loads) {
    h("loads.node_set", l.node_set)("loads.kind", double(l.kind))("loads.component", l.component);
    h.list("loads.t", l.amplitude.t).list("loads.v", l.amplitude.v);
  }
  h("time.T", c.time.T)("time.steps", c.time.steps);
  // Left out: the numerical controls a failure message asks to change (controls_fingerprint()
  // below), so that a failed run restarts with them changed (README "When a run fails").
  h("solver.local_iterations", c.solver.local_iterations);
  h("solver.rho", double(c.solver.rho))("solver.active_set", c.solver.active_set);
  h("solver.springs_follow_beta", c.solver.springs_follow_beta);
  h("solver.active_set_max_nodes", c.solver.active_set_max_nodes)("solver.compressed_min_nodes", c.solver.compressed_min_nodes);
  // solver.linear is left out: the body's solver changes the results by round-off only, and a
  // run interrupted in one process may go on under mpirun.
  const IntegratorParams& A = c.integrator;
  // The default table spelled out is the default (hashed as empty, as before it could be named).
  const bool default_table = A.scheme == ArkodeScheme::Dirk && A.table == IntegratorParams::default_dirk_table;
  h("integrator.method", double(A.method))("integrator.scheme", double(A.scheme))
      ("integrator.table", default_table ? std::string() : A.table);
  h("integrator.initial_step", A.initial_step)("integrator.fixed_step", A.fixed_step);
  h.list("output.times", c.output.times);
  for (const NamedPoint& p : c.output.watch) h("output.watch.name", p.name).list("output.watch.point", p.point);
  for (const NamedPoint& p : c.output.probes) h("output.probes.name", p.name).list("output.probes.point", p.point);
  return h;
}

}  // namespace

std::string Config::fingerprint() const { return hash_settings(*this).hex(); }

std::string Config::fingerprint_parts() const { return hash_settings(*this).parts(); }

std::string differing_settings(const std::string& parts, const std::string& other) {
  if (parts.empty() || other.empty()) return "";
  const auto by_name = [](const std::string& text) {
    std::map<std::string, std::string> digest;
    std::size_t begin = 0;
    while (begin < text.size()) {
      const std::size_t end = std::min(text.find(' ', begin), text.size()), eq = text.find('=', begin);
      if (eq < end) digest[text.substr(begin, eq - begin)] = text.substr(eq + 1, end - eq - 1);
      begin = end + 1;
    }
    return digest;
  };
  std::map<std::string, std::string> a = by_name(parts), b = by_name(other);
  std::vector<std::string> names;
  for (const auto& [name, digest] : a)
    if (b[name] != digest) names.push_back(name);
  for (const auto& [name, digest] : b)
    if (a.count(name) == 0) names.push_back(name);
  return names.empty() ? "" : comma_list(names) + (names.size() == 1 ? " differs" : " differ");
}

std::string Config::controls_fingerprint() const {
  Hash h;
  h("solver.method", double(solver.method))("solver.form", double(solver.form))("solver.relaxation", solver.relaxation);
  h("solver.over_relaxation", solver.over_relaxation)("solver.tolerance", solver.tolerance);
  h("solver.max_iterations", solver.max_iterations)("solver.anderson", solver.anderson);
  // Hashed where not 1, so that a report written before the setting came (plain sweeps) keeps its controls.
  if (solver.block_sweeps != 1) h("solver.block_sweeps", solver.block_sweeps);
  const IntegratorParams& A = integrator;
  h("integrator.rtol", A.rtol)("integrator.atol", A.atol)("integrator.min_step", A.min_step);
  h("integrator.max_step", A.max_step)("integrator.max_steps", A.max_steps);
  h("integrator.fixed_point_tolerance", A.fixed_point_tolerance)("integrator.fixed_point_iterations", A.fixed_point_iterations);
  return h.hex();
}

std::string Config::where(const std::string& path) const {
  const auto origin = origins.find(path);
  if (origin != origins.end()) return origin->second;
  const auto it = lines.find(path);
  if (it == lines.end()) return file + ": " + path;  // a default, or a setting read before the lines were kept
  if (it->second == 0) return "--set " + path;  // on the command line
  return file + ":" + std::to_string(it->second) + ": " + path;
}

const char* hypothesis_name(Hypothesis h) {
  switch (h) {
    case Hypothesis::PlaneStrain: return "plane_strain";
    case Hypothesis::PlaneStress: return "plane_stress";
    case Hypothesis::Axisymmetric: return "axisymmetric";
  }
  return "";
}

const char* method_name(Method m) {
  switch (m) {
    case Method::Arkode: return "arkode";
    case Method::Euler: return "euler";
    case Method::RateIndependent: return "rate-independent";
    case Method::ContactOnly: return "contact-only";
  }
  return "";
}

bool alpha_zero_everywhere(const Config& cfg) {
  return std::all_of(cfg.interfaces.begin(), cfg.interfaces.end(), [](const InterfaceParams& p) { return p.alpha == 0; });
}

Method rate_independent_limit(Method m) {
  return m == Method::ContactOnly ? m : Method::RateIndependent;
}

const char* contact_method_name(ContactMethod m) {
  switch (m) {
    case ContactMethod::Rccm: return "rccm";
    case ContactMethod::Newton: return "newton";
    case ContactMethod::Bipotential: break;
  }
  return "bipotential";
}

std::vector<std::string> unused_settings(const Config& cfg) {
  const SolverParams& S = cfg.solver;
  const bool bipotential = S.method == ContactMethod::Bipotential;
  const bool gauss_seidel = bipotential && S.form == SweepForm::GaussSeidel;
  const Method m = cfg.integrator.method;
  const std::string solver = std::string("the \"") + contact_method_name(S.method) + "\" solver";
  const bool limit = alpha_zero_everywhere(cfg);
  const std::string integrator = std::string("the \"") + method_name(m) + "\" integrator" +
                                 (m == Method::RateIndependent && limit ? " (alpha = 0 on every interface)" : "");
  const std::string cholmod = "CHOLMOD (solver.linear = \"cholmod\", or \"auto\" in one process)";
  const std::string linear_solver = S.linear.kind == LinearSolver::Cholmod ? cholmod : "PETSc CG + GAMG (solver.linear = \"cg-gamg\")";
  const std::string active_set = solver + (bipotential ? " without its exact step (solver.active_set = false)" : "");
  struct Use {
    const char* path;
    bool read;             // by this run's methods
    const std::string& by; // the method of this run that does not read it
    const char* readers;   // who reads it
  };
  const std::vector<Use> uses{
      {"solver.over_relaxation", S.method == ContactMethod::Rccm, solver, "the \"rccm\" solver"},
      {"solver.local_iterations", gauss_seidel || S.method == ContactMethod::Newton, solver,
       "the \"bipotential\" solver's Gauss-Seidel form and the \"newton\" solver"},
      {"solver.form", bipotential, solver, "the \"bipotential\" solver"},
      {"solver.anderson", gauss_seidel, solver, "the \"bipotential\" solver's Gauss-Seidel form"},
      {"solver.block_sweeps", gauss_seidel, solver, "the \"bipotential\" solver's Gauss-Seidel form"},
      {"solver.relaxation", bipotential && !gauss_seidel, solver, "the \"bipotential\" solver's Jacobi form"},
      {"solver.active_set", bipotential, solver, "the \"bipotential\" solver"},
      {"solver.active_set_max_nodes", bipotential && S.active_set, active_set, "the \"bipotential\" solver's exact step"},
      {"solver.compressed_min_nodes", S.reads_compressed_W0(), solver, "the \"bipotential\" and \"newton\" solvers"},
      {"integrator.scheme", m == Method::Arkode, integrator, "\"arkode\""},
      {"integrator.table", m == Method::Arkode, integrator, "\"arkode\""},
      {"integrator.rtol", m == Method::Arkode, integrator, "\"arkode\""},
      {"integrator.atol", m == Method::Arkode, integrator, "\"arkode\""},
      {"integrator.max_step", m == Method::Arkode, integrator, "\"arkode\""},
      {"integrator.initial_step", m == Method::Arkode, integrator, "\"arkode\""},
      {"integrator.fixed_step", m == Method::Arkode, integrator, "\"arkode\" (the fixed-step methods take time.steps)"},
      {"integrator.min_step", m == Method::Arkode, integrator, "\"arkode\""},
      {"integrator.max_steps", m == Method::Arkode, integrator, "\"arkode\""},
      {"integrator.fixed_point_tolerance", m == Method::RateIndependent, integrator, "\"rate-independent\""},
      {"integrator.fixed_point_iterations", m == Method::RateIndependent, integrator, "\"rate-independent\""},
      {"solver.linear_tolerance", S.linear.kind != LinearSolver::Cholmod, cholmod,
       "solver.linear = \"cg-gamg\" and \"mumps\" (\"auto\" under mpirun)"},
      {"solver.out_of_core", S.linear.kind == LinearSolver::Mumps, linear_solver,
       "solver.linear = \"mumps\" (\"auto\" under mpirun)"}};
  std::vector<std::string> notes;
  for (const Use& u : uses)
    if (!u.read && cfg.lines.count(u.path))
      notes.push_back(cfg.where(u.path) + ": not read by " + u.by + ", only by " + u.readers + "; it has no effect on this run");
  return notes;
}

}  // namespace rccm

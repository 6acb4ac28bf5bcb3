#include "rccm/io/checkpoint.hpp"

#include "rccm/io/atomic_file.hpp"
#include "rccm/io/csv.hpp"
#include "rccm/base/errors.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace rccm {

namespace {

// 2: no step records (history.csv holds them); 3: contact_nodes; 4: the settings fingerprint
// without the numerical controls (a failed run restarts with them changed); 5: the springs' beta
// and the condensation counts; 6: the notes the run has said (RunNotes); 7: the settings' digests
// after the fingerprint (a refused restart names what differs; format 6 is read too)
const char* const magic = "rccm-checkpoint-7";
const char* const magic_6 = "rccm-checkpoint-6";

/// One record per line: a name, then numbers (hex floats) or, for `text`, the rest of the line.
class RecordWriter {
 public:
  explicit RecordWriter(std::ostream& out) : out_(out) {}
  void number(const char* name, double v) { out_ << name << ' ' << hex(v) << '\n'; }
  void vector(const char* name, const Eigen::VectorXd& v) {
    out_ << name << ' ' << v.size();
    for (double x : v) out_ << ' ' << hex(x);
    out_ << '\n';
  }
  void text(const char* name, const std::string& s) { out_ << name << ' ' << s << '\n'; }

 private:
  static std::string hex(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%a", v);
    return buf;
  }
  std::ostream& out_;
};

/// Reads the records back in the order they were written; a wrong name or number is an
/// InputError "file:line: what was expected".
class RecordReader {
 public:
  RecordReader(std::istream& in, std::string path) : in_(in), path_(std::move(path)) {}

  double number(const char* name) {
    std::istringstream line = next(name);
    return parse(line, name);
  }
  int integer(const char* name) { return static_cast<int>(number(name)); }
  Eigen::VectorXd vector(const char* name) {
    std::istringstream line = next(name);
    const double n = parse(line, name);
    if (!(n >= 0 && n < 1e9)) fail(std::string("a length for '") + name + "'");
    Eigen::VectorXd v(static_cast<Eigen::Index>(n));
    for (double& x : v) x = parse(line, name);
    return v;
  }
  std::string text(const char* name) {
    std::istringstream line = next(name);
    std::string rest;
    std::getline(line >> std::ws, rest);
    return rest;
  }
  /// A value read on the last line that breaks a rule of the state: refused, naming the line.
  void check(bool ok, const std::string& rule) const {
    if (!ok)
      throw InputError(path_ + ":" + std::to_string(line_) + ": " + rule +
                       " (a damaged checkpoint; start the run afresh with --force)");
  }
  /// A count: a whole number in [0, max].
  long count(const char* name, double max) {
    const double v = number(name);
    check(v >= 0 && v <= max && v == std::floor(v), std::string(name) + " must be a whole number in [0, " +
                                                        std::to_string(static_cast<long>(max)) + "]");
    return static_cast<long>(v);
  }
  [[noreturn]] void fail(const std::string& expected) const {
    throw InputError(path_ + ":" + std::to_string(line_) + ": expected " + expected +
                     " (a damaged checkpoint; start the run afresh with --force)");
  }

 private:
  std::istringstream next(const char* name) {
    std::string line;
    ++line_;
    if (!read_line(in_, line)) fail(std::string("'") + name + "', found the end of the file");
    std::istringstream s(line);
    std::string word;
    if (!(s >> word) || word != name) fail(std::string("'") + name + "'");
    return s;
  }
  double parse(std::istringstream& line, const char* name) {
    std::string word;
    if (!(line >> word)) fail(std::string("more numbers for '") + name + "'");
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(word.c_str(), &end);  // reads hex floats exactly
    if (*end != '\0' || errno == ERANGE) fail(std::string("a number for '") + name + "', found '" + word + "'");
    return v;
  }
  std::istream& in_;
  std::string path_;
  int line_ = 0;
};

Eigen::VectorXd status_vector(const std::vector<Status>& status) {
  Eigen::VectorXd v(static_cast<Eigen::Index>(status.size()));
  for (std::size_t i = 0; i < status.size(); ++i) v[static_cast<Eigen::Index>(i)] = static_cast<int>(status[i]);
  return v;
}

}  // namespace

std::string checkpoint_path(const std::string& directory) { return directory + "/checkpoint.txt"; }

void write_checkpoint(const std::string& directory, const Checkpoint& c) {
  AtomicFile file(checkpoint_path(directory));
  RecordWriter w(file.stream());
  const RunResult& p = c.progress;
  w.text(magic, "");
  w.text("settings", c.settings + (c.settings_parts.empty() ? "" : " " + c.settings_parts));
  w.number("step", c.step);
  w.number("last_step", c.last_step);
  w.number("t", c.state.t);
  w.vector("beta", c.state.beta);
  w.vector("Rbar", c.state.Rbar);
  w.vector("u", c.state.u);
  w.vector("y", c.state.y);
  w.vector("status", status_vector(c.state.status));
  w.vector("springs_beta", c.springs_beta);
  const EnergyTerms& e = c.energy;
  w.vector("energy", Eigen::Vector<double, 6>(e.external_work, e.strain_energy, e.free_energy_change,
                                              e.damage_dissipation, e.friction_dissipation, e.normal_contact_work));
  w.vector("peak_force", Eigen::Map<const Eigen::VectorXd>(p.peak_force.data(), Eigen::Index(p.peak_force.size())));
  w.vector("peak_time", Eigen::Map<const Eigen::VectorXd>(p.peak_time.data(), Eigen::Index(p.peak_time.size())));
  w.vector("solves", Eigen::Vector<double, 6>(double(p.solves.contact_solves), double(p.solves.sweeps),
                                              p.solves.max_sweeps, p.solves.seconds, double(p.solves.condensations),
                                              p.solves.condense_seconds));
  const IntegratorStats& I = p.integrator;
  w.vector("integrator", Eigen::Vector4d(double(I.steps), double(I.rejected), double(I.rhs_evaluations),
                                         double(I.newton_iterations)));
  w.number("snapshots", double(p.snapshots.size()));
  for (const Snapshot& s : p.snapshots) {
    w.number("snapshot_t", s.t);
    w.number("debonded_length", s.debonded_length);
    w.vector("snapshot_beta", s.beta);
    w.vector("snapshot_Rbar", s.Rbar);
    w.vector("snapshot_u", s.u);
  }
  w.vector("diagnostics", Eigen::Map<const Eigen::VectorXd>(c.diagnostics.data(), Eigen::Index(c.diagnostics.size())));
  w.vector("excursion", Eigen::Vector3d(c.excursion.size, c.excursion.t, c.excursion.node));
  w.number("notes", double(c.notes.said.size()));
  for (const std::string& note : c.notes.said) w.text("note", note);
  w.vector("deformation", Eigen::Vector2d(c.notes.deformation_noted, c.notes.deformation_checked));
  w.vector("contact_nodes",
           Eigen::Map<const Eigen::VectorXi>(c.contact_nodes.data(), Eigen::Index(c.contact_nodes.size())).cast<double>());
  w.text("end", "");
  file.commit();
}

Checkpoint read_checkpoint(const std::string& directory, const Config& cfg) {
  const std::string path = checkpoint_path(directory);
  std::ifstream in(path);
  if (!in)
    throw InputError(path + ": no checkpoint to restart from (a run writes one every output.checkpoint_steps "
                            "steps and when it stops)");
  std::string format;  // a checkpoint of another version of rccm is not damaged: say so
  if ((in >> format) && format.rfind("rccm-checkpoint-", 0) == 0 && format != magic && format != magic_6)
    throw InputError(path + ": written by another version of rccm (format " + format + ", this version reads " + magic +
                     "); start the run afresh with --force");
  in.clear();
  in.seekg(0);
  RecordReader r(in, path);
  const auto finite = [](const Eigen::VectorXd& v) { return v.allFinite(); };
  Checkpoint c;
  r.text(format == magic_6 ? magic_6 : magic);
  const std::string settings = r.text("settings");
  c.settings = settings.substr(0, settings.find(' '));
  c.settings_parts = settings.size() > c.settings.size() ? settings.substr(c.settings.size() + 1) : "";
  if (c.settings != cfg.settings) {
    const std::string names = differing_settings(c.settings_parts, cfg.settings_parts);
    throw InputError(path + ": written by a run of other settings than " + cfg.file + " with these --set options" +
                     (names.empty() ? "" : ": " + names) +
                     " (the mesh file's contents count too: an edited or remeshed .geo/.msh is another problem); restart "
                     "with the same config, options and mesh, or run afresh with --force");
  }
  c.step = static_cast<int>(r.count("step", 2e9));
  c.last_step = r.number("last_step");
  r.check(std::isfinite(c.last_step) && c.last_step >= 0 && c.last_step <= cfg.time.T,
          "last_step must be in [0, time.T]");
  c.state.t = r.number("t");
  r.check(c.state.t >= 0 && c.state.t <= cfg.time.T, "t must be in [0, time.T = " + std::to_string(cfg.time.T) + "]");
  c.state.beta = r.vector("beta");
  r.check(finite(c.state.beta) && c.state.beta.size() > 0 && c.state.beta.minCoeff() >= 0 &&
              c.state.beta.maxCoeff() <= 1,
          "beta must be in [0, 1]");
  const long m = c.state.beta.size();
  for (Eigen::VectorXd* v : {&c.state.Rbar, &c.state.u, &c.state.y}) {
    const char* name = v == &c.state.Rbar ? "Rbar" : v == &c.state.u ? "u" : "y";
    *v = r.vector(name);
    r.check(finite(*v), std::string(name) + " must be finite");
    r.check((v->size() == 2 * m || v->size() == 3 * m) && v->size() == c.state.Rbar.size(),
            std::string(name) + " must have 2 or 3 components per contact node");
  }
  for (double s : r.vector("status")) {
    if (s != 0 && s != 1 && s != 2) r.fail("a status 0, 1 or 2");
    c.state.status.push_back(static_cast<Status>(int(s)));
  }
  r.check(long(c.state.status.size()) == m, "status must have one entry per contact node");
  c.springs_beta = r.vector("springs_beta");  // set at an earlier beta, which only falls
  r.check(c.springs_beta.size() == m && finite(c.springs_beta) && (c.springs_beta.array() >= c.state.beta.array()).all() &&
              c.springs_beta.maxCoeff() <= 1,
          "springs_beta must be in [beta, 1], one per contact node");
  const Eigen::VectorXd e = r.vector("energy");
  r.check(e.size() == 6 && finite(e), "energy must be 6 finite terms");
  c.energy = {e[0], e[1], e[2], e[3], e[4], e[5]};
  RunResult& p = c.progress;
  const Eigen::VectorXd peak_force = r.vector("peak_force");
  r.check(finite(peak_force) && long(peak_force.size()) == long(cfg.loads.size()), "one finite peak force per load");
  const Eigen::VectorXd peak_time = r.vector("peak_time");
  r.check(peak_time.size() == peak_force.size() && finite(peak_time), "one finite peak time per load");
  p.peak_force.assign(peak_force.begin(), peak_force.end());
  p.peak_time.assign(peak_time.begin(), peak_time.end());
  const Eigen::VectorXd solves = r.vector("solves"), integrator = r.vector("integrator");
  r.check(solves.size() == 6 && integrator.size() == 4 && finite(solves) && finite(integrator) &&
              solves.minCoeff() >= 0 && integrator.minCoeff() >= 0,
          "6 solve and 4 integrator counts, none negative");
  p.solves = {long(solves[0]), long(solves[1]), int(solves[2]), solves[3], long(solves[4]), solves[5]};
  p.integrator = {long(integrator[0]), long(integrator[1]), long(integrator[2]), long(integrator[3]), {}};
  for (long k = r.count("snapshots", 1e6); k > 0; --k) {
    Snapshot s;
    s.t = r.number("snapshot_t");
    r.check(s.t >= 0 && s.t <= c.state.t, "a snapshot's time must be in [0, t]");
    s.debonded_length = r.number("debonded_length");
    s.beta = r.vector("snapshot_beta");
    s.Rbar = r.vector("snapshot_Rbar");
    s.u = r.vector("snapshot_u");
    r.check(s.beta.size() == m && s.Rbar.size() == c.state.Rbar.size() && s.u.size() == c.state.u.size() &&
                finite(s.beta) && finite(s.Rbar) && finite(s.u),
            "a snapshot must have finite vectors of the state's sizes");
    p.snapshots.push_back(std::move(s));
  }
  const Eigen::VectorXd diagnostics = r.vector("diagnostics");
  r.check(finite(diagnostics), "diagnostics must be finite");
  c.diagnostics.assign(diagnostics.begin(), diagnostics.end());
  const Eigen::VectorXd excursion = r.vector("excursion");
  r.check(excursion.size() == 3 && finite(excursion) && excursion[2] >= -1 && excursion[2] < m,
          "excursion must be 3 numbers (size, t, contact node)");
  c.excursion = {excursion[0], excursion[1], int(excursion[2])};
  for (long k = r.count("notes", 1e3); k > 0; --k) c.notes.said.push_back(r.text("note"));
  const Eigen::VectorXd deformation = r.vector("deformation");
  r.check(deformation.size() == 2 && (deformation[0] == 0 || deformation[0] == 1) && deformation[1] <= c.state.t,
          "deformation must be 2 numbers (noted 0 or 1, the last check's time, at most t)");
  c.notes.deformation_noted = deformation[0] == 1;
  c.notes.deformation_checked = deformation[1];
  const Eigen::VectorXd nodes = r.vector("contact_nodes");
  r.check(nodes.size() == m && (nodes.array() >= 0).all() && (nodes.array() < 2147483647.0).all() &&
              (nodes.array() == nodes.array().floor()).all(),  // NaN and inf fail the comparisons
          "contact_nodes must be one mesh node per contact node");
  c.contact_nodes.assign(nodes.begin(), nodes.end());
  r.text("end");
  return c;
}

}  // namespace rccm

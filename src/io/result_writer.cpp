#include "rccm/io/result_writer.hpp"

#include "rccm/io/atomic_file.hpp"
#include "rccm/base/errors.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace rccm {

namespace {

/// Writes a value with enough digits to read back what was computed (to 1e-10): the first
/// cell of a line, then ",value" cells.
void first_cell(std::ostream& out, double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.12g", v);
  out << buf;
}
void cell(std::ostream& out, double v) { first_cell(out << ",", v); }

std::string load_label(const Config& cfg, std::size_t k) {
  const LoadParams& p = cfg.loads[k];
  return "L" + std::to_string(k) + " " + p.node_set + "." + "xy"[p.component];
}

const char* load_unit(LoadKind kind) {
  switch (kind) {
    case LoadKind::Displacement: return "mm";
    case LoadKind::Force: return "N";
    default: return "MPa";
  }
}

std::ofstream open(const std::string& path, std::ios::openmode mode = std::ios::out) {
  std::ofstream out(path, mode);
  if (!out) throw InputError("output.directory: cannot write " + path);
  return out;
}

std::string interface_file(double t) {
  char name[64];
  std::snprintf(name, sizeof name, "interface_t%.12g.csv", t);  // the time as in history.csv
  return name;
}

/// Keeps the header and the complete lines of a CSV stream up to time t (its first field).
void keep_lines_until(const std::string& path, double t) {
  std::ifstream in(path);
  std::string header, line;
  std::getline(in, header);
  const auto fields = [](const std::string& l) { return std::count(l.begin(), l.end(), ','); };
  AtomicFile file(path);
  file.stream() << header << "\n";
  const double eps = 1e-9 * std::max(1.0, std::abs(t));
  while (std::getline(in, line) && fields(line) == fields(header) && std::strtod(line.c_str(), nullptr) <= t + eps)
    file.stream() << line << "\n";
  file.commit();
}

/// Appends one complete line with a single write, so that a reader never sees half of it.
void write_line(std::ofstream& out, const std::ostringstream& line) {
  const std::string text = line.str() + "\n";
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  out.flush();
  if (!out) throw SolveError("cannot append to a result file (disk full?)");
}

/// The labels of a pair's local components in column names, normal first: n, t (2D) or n, t1, t2 (3D).
std::vector<std::string> component_labels(int dim) {
  if (dim == 2) return {"n", "t"};
  return {"n", "t1", "t2"};
}

/// Pair i's local vector v in the columns' order: normal first, then the tangential components.
std::vector<double> normal_first(const Layout& L, const Eigen::VectorXd& v, int i) {
  std::vector<double> out{v[L.normal(i)]};
  for (int k = 0; k < L.tangential_size(); ++k) out.push_back(v[L.offset(i) + k]);
  return out;
}

}  // namespace

ResultWriter::ResultWriter(const Model& model, const Config& cfg, const std::string& directory,
                           const ResumePoint* resume)
    : model_(model), cfg_(cfg), directory_(directory), vtk_(model, directory) {
  if (resume) {
    keep_lines_until(directory + "/history.csv", resume->t);
    keep_lines_until(directory + "/curves.csv", resume->t);
    history_ = open(directory + "/history.csv", std::ios::app);
    curves_ = open(directory + "/curves.csv", std::ios::app);
    std::vector<std::string> keep;
    for (double t : resume->output_times) keep.push_back(interface_file(t));
    for (const auto& entry : std::filesystem::directory_iterator(directory)) {
      const std::string name = entry.path().filename().string();
      if (name.rfind("interface_t", 0) == 0 && std::find(keep.begin(), keep.end(), name) == keep.end())
        std::filesystem::remove(entry.path());
    }
    vtk_.resume(resume->output_times);
    return;
  }
  history_ = open(directory + "/history.csv");
  curves_ = open(directory + "/curves.csv");

  std::ostringstream h;
  h << "t [s],dt [s],contact solves,sweeps mean,sweeps max,residual,min beta,stick,slide,separated,"
       "equilibrium residual,step wall [s]";
  const std::vector<std::string> components = component_labels(model.mesh().dim);
  for (const WatchPoint& w : cfg.output.watch) {
    h << "," << w.name << " beta";
    for (const char* q : {"u", "Radh", "Rbar"})
      for (const std::string& c : components) h << "," << w.name << " " << q << "_" << c << (q[0] == 'u' ? " [mm]" : " [N]");
  }
  write_line(history_, h);

  std::ostringstream c;
  c << "t [s]";
  for (std::size_t k = 0; k < cfg.loads.size(); ++k)
    c << "," << load_label(cfg, k) << " value [" << load_unit(cfg.loads[k].kind) << "]," << load_label(cfg, k)
      << " force [N]";
  c << ",external work [N mm],strain energy [N mm],interface free energy change [N mm],"
       "damage dissipation [N mm],friction dissipation [N mm],normal contact work [N mm],imbalance [N mm]";
  write_line(curves_, c);
}

void ResultWriter::step(const AcceptedStep& a, const BodyState& b, const EnergyTerms& e) {
  int count[3] = {0, 0, 0};
  for (Status x : a.state.status) ++count[static_cast<int>(x)];
  std::ostringstream h;
  first_cell(h, a.t);
  for (double v : {a.dt, double(a.counts.contact_solves),
                   double(a.counts.sweeps) / std::max(1L, a.counts.contact_solves), double(a.counts.max_sweeps),
                   a.solution.residual, a.state.beta.minCoeff(), double(count[1]), double(count[2]), double(count[0]),
                   a.residuals.equilibrium, a.cpu_seconds})
    cell(h, v);
  const Layout& L = model_.interface().layout;
  const Eigen::VectorXd Radh = adhesive_forces(model_, a.state);
  for (int i : model_.watched()) {
    cell(h, a.state.beta[i]);
    for (const Eigen::VectorXd* v : {&a.state.u, &Radh, &a.state.Rbar})
      for (double x : normal_first(L, *v, i)) cell(h, x);
  }
  write_line(history_, h);

  std::ostringstream c;
  first_cell(c, a.t);
  for (std::size_t k = 0; k < b.value.size(); ++k) cell(c, b.value[k]), cell(c, b.force[k]);
  for (double v : {e.external_work, e.strain_energy, e.free_energy_change, e.damage_dissipation,
                   e.friction_dissipation, e.normal_contact_work, e.imbalance()})
    cell(c, v);
  write_line(curves_, c);
}

void ResultWriter::output(const InterfaceState& s, const BodyState& b) {
  AtomicFile file(directory_ + "/" + interface_file(s.t));
  std::ostream& out = file.stream();
  const Interface& I = model_.interface();
  const Layout& L = I.layout;
  const std::vector<std::string> components = component_labels(L.dim);
  out << "node,x [mm],y [mm],a [mm],t [s],beta";
  for (const char* q : {"u", "Rbar", "Radh", "r", "p"})
    for (const std::string& c : components)
      out << "," << q << "_" << c << (q[0] == 'u' ? " [mm]" : q[0] == 'p' ? " [MPa]" : " [N]");
  out << ",status\n";
  const Eigen::VectorXd Radh = b.r - s.Rbar;
  for (int i = 0; i < I.size(); ++i) {
    const Eigen::Vector3d& x = model_.mesh().nodes[I.pairs[i].node];
    const double a = I.pairs[i].measure;
    out << i;
    for (double v : {x.x(), x.y(), a, s.t, s.beta[i]}) cell(out, v);
    for (const Eigen::VectorXd* v : {&s.u, &s.Rbar, &Radh, &b.r})
      for (double x : normal_first(L, *v, i)) cell(out, x);
    for (double x : normal_first(L, b.r, i)) cell(out, x / a);
    out << "," << status_name(s.status[i]) << "\n";
  }
  file.commit();
  vtk_.write(s, b);
}

}  // namespace rccm

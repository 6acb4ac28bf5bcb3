#include "rccm/result_writer.hpp"

#include "rccm/atomic_file.hpp"
#include "rccm/errors.hpp"

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

}  // namespace

ResultWriter::ResultWriter(const Model& model, const std::string& directory, const ResumePoint* resume)
    : model_(model), directory_(directory), vtk_(model, directory) {
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
  for (const WatchPoint& w : model.config().output.watch)
    for (const char* q : {"beta", "u_n [mm]", "u_t [mm]", "Radh_n [N]", "Radh_t [N]", "Rbar_n [N]", "Rbar_t [N]"})
      h << "," << w.name << " " << q;
  write_line(history_, h);

  std::ostringstream c;
  c << "t [s]";
  for (std::size_t k = 0; k < model.config().loads.size(); ++k)
    c << "," << load_label(model.config(), k) << " value [" << load_unit(model.config().loads[k].kind) << "],"
      << load_label(model.config(), k) << " force [N]";
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
  const Interface& I = model_.interface();
  for (int i : model_.watched()) {
    const Vec2 Radh = adhesive_force(I.a[i], a.state.beta[i], I.Ct, I.Cn, a.state.u.segment<2>(2 * i));
    for (double v : {a.state.beta[i], a.state.u[2 * i + 1], a.state.u[2 * i], Radh[1], Radh[0],
                     a.state.Rbar[2 * i + 1], a.state.Rbar[2 * i]})
      cell(h, v);
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
  out << "node,x [mm],y [mm],a [mm],t [s],beta,u_n [mm],u_t [mm],Rbar_n [N],Rbar_t [N],Radh_n [N],Radh_t [N],"
         "r_n [N],r_t [N],p_n [MPa],p_t [MPa],status\n";
  const Interface& I = model_.interface();
  for (int i = 0; i < I.size(); ++i) {
    const Eigen::Vector2d& x = model_.mesh().nodes[I.nodes[i]];
    const Vec2 r = b.r.segment<2>(2 * i), Rbar = s.Rbar.segment<2>(2 * i), Radh = r - Rbar;
    out << i;
    for (double v : {x.x(), x.y(), I.a[i], s.t, s.beta[i], s.u[2 * i + 1], s.u[2 * i], Rbar[1], Rbar[0], Radh[1],
                     Radh[0], r[1], r[0], r[1] / I.a[i], r[0] / I.a[i]})
      cell(out, v);
    out << "," << status_name(s.status[i]) << "\n";
  }
  file.commit();
  vtk_.write(s, b);
}

}  // namespace rccm

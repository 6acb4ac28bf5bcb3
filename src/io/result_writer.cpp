#include "rccm/io/result_writer.hpp"

#include "rccm/base/errors.hpp"
#include "rccm/io/atomic_file.hpp"
#include "rccm/io/output_directory.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace rccm {

std::string load_label(const Config& cfg, std::size_t k) {
  const LoadParams& p = cfg.loads[k];
  const std::string along = p.kind == LoadKind::Pressure ? "n" : std::string(1, "xyz"[p.component]);
  return "L" + std::to_string(k) + " " + p.node_set + "." + along;
}

namespace {

const char* load_unit(LoadKind kind) {
  switch (kind) {
    case LoadKind::Displacement: return "mm";
    case LoadKind::Force: return "N";
    case LoadKind::Traction:
    case LoadKind::Pressure: return "MPa";
  }
  return "";
}

std::string interface_file(double t) { return "interface_t" + csv_number(t) + ".csv"; }  // the time as in history.csv

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

std::vector<std::string> history_header(const Config& cfg, int dim) {
  std::vector<std::string> h = history_run_columns();
  for (const NamedPoint& w : cfg.output.watch) {
    const std::vector<std::string> columns = history_point_columns(w.name, true, dim);
    h.insert(h.end(), columns.begin(), columns.end());
  }
  for (const NamedPoint& p : cfg.output.probes) {
    const std::vector<std::string> columns = history_point_columns(p.name, false, dim);
    h.insert(h.end(), columns.begin(), columns.end());
  }
  return h;
}

std::vector<std::string> curves_header(const Config& cfg) {
  std::vector<std::string> h = {"t [s]"};
  for (std::size_t k = 0; k < cfg.loads.size(); ++k) {
    h.push_back(load_label(cfg, k) + " value [" + load_unit(cfg.loads[k].kind) + "]");
    h.push_back(load_label(cfg, k) + " force [N]");
    h.push_back(load_label(cfg, k) + " displacement [mm]");
  }
  h.push_back(cfg.mesh.dim() == 3 ? "debonded area [mm2]" : "debonded length [mm]");
  for (const char* q : {"external work [N mm]", "strain energy [N mm]",
                        "interface free energy change [N mm]", "damage dissipation [N mm]",
                        "friction dissipation [N mm]", "normal contact work [N mm]", "imbalance [N mm]"})
    h.push_back(q);
  return h;
}

}  // namespace

std::vector<std::string> history_run_columns() {
  return {"t [s]",    "dt [s]",   "contact solves", "sweeps mean",          "sweeps max",
          "residual", "min beta", "stick",          "slide",                "separated",
          "equilibrium residual",   "step wall [s]"};
}

std::vector<std::string> history_point_columns(const std::string& name, bool watch, int dim) {
  std::vector<std::string> h;
  if (!watch) {
    for (int c = 0; c < dim; ++c) h.push_back(name + " u_" + "xyz"[c] + " [mm]");
    return h;
  }
  h.push_back(name + " beta");
  for (const char* q : {"u", "Radh", "Rbar"})
    for (const std::string& c : component_labels(dim))
      h.push_back(name + " " + q + "_" + c + (q[0] == 'u' ? " [mm]" : " [N]"));
  return h;
}

double debonded_length(const Model& model, const Eigen::VectorXd& beta) {
  double length = 0;
  for (int i = 0; i < model.contact_nodes(); ++i)
    if (beta[i] < 0.5) length += model.interface().pairs[i].length;
  return length;
}

ResultWriter::ResultWriter(const Model& model, const Config& cfg, const std::string& directory,
                           const ResumePoint* resume)
    : model_(model), cfg_(cfg), directory_(directory), vtk_(model, directory) {
  const std::string history = directory + "/history.csv", curves = directory + "/curves.csv";
  if (!resume) {
    history_ = std::make_unique<CsvStream>(history, history_header(cfg, model.mesh().dim));
    curves_ = std::make_unique<CsvStream>(curves, curves_header(cfg));
    return;
  }
  // Both read (and refused if cut short) before either is taken up.
  const CsvStream::Kept history_rows = CsvStream::lines_until(history, resume->t),
                        curves_rows = CsvStream::lines_until(curves, resume->t);
  history_ = std::make_unique<CsvStream>(history, history_rows);
  curves_ = std::make_unique<CsvStream>(curves, curves_rows);
  // Its kept rows (the same columns: the settings are the checkpoint's) are the step records.
  for (std::size_t row = 1; row < history_rows.lines.size(); ++row) {
    const std::vector<std::string> f = csv_split(history_rows.lines[row]);
    const auto at = [&](std::size_t k) { return std::strtod(f.at(k).c_str(), nullptr); };
    resumed_steps_.push_back({int(row) - 1, at(0), at(1), long(at(2)), at(3), int(at(4)), at(11)});
  }
  // The interface files of output times after t go (a run stopped after its checkpoint wrote
  // them); only files named as the run names them: a user's interface_threshold.vtp stays.
  std::vector<std::string> keep;
  for (double t : resume->output_times) keep.push_back(interface_file(t));
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(directory)) {
    const std::string name = entry.path().filename().string();
    if (interface_time_file(name) && entry.is_regular_file(ec) && std::find(keep.begin(), keep.end(), name) == keep.end())
      std::filesystem::remove(entry.path());
  }
  vtk_.resume(resume->t, resume->frame_at_t);
}

void ResultWriter::step(const AcceptedStep& a, const BodyState& b, const EnergyTerms& e) {
  int count[3] = {0, 0, 0};
  for (Status x : a.state.status) ++count[static_cast<int>(x)];
  std::vector<double> h = {a.t,
                           a.dt,
                           double(a.counts.contact_solves),
                           a.counts.sweeps_per_solve(),
                           double(a.counts.max_sweeps),
                           a.solution.residual,
                           a.state.beta.minCoeff(),
                           double(count[1]),
                           double(count[2]),
                           double(count[0]),
                           a.residuals.equilibrium,
                           a.wall_seconds};
  const Layout& L = model_.interface().layout;
  const Eigen::VectorXd Radh = adhesive_forces(model_, a.state);
  for (int i : model_.watched()) {
    h.push_back(a.state.beta[i]);
    for (const Eigen::VectorXd* v : {&a.state.u, &Radh, &a.state.Rbar})
      for (double x : normal_first(L, *v, i)) h.push_back(x);
  }
  h.insert(h.end(), b.probes.begin(), b.probes.end());
  history_->append(h);

  std::vector<double> c = {a.t};
  for (std::size_t k = 0; k < b.value.size(); ++k) c.insert(c.end(), {b.value[k], b.force[k], b.displacement[k]});
  c.insert(c.end(), {debonded_length(model_, a.state.beta), e.external_work, e.strain_energy, e.free_energy_change,
                     e.damage_dissipation, e.friction_dissipation, e.normal_contact_work, e.imbalance()});
  curves_->append(c);
}

void ResultWriter::output(const InterfaceState& s, const BodyState& b) {
  AtomicFile file(directory_ + "/" + interface_file(s.t));
  std::ostream& out = file.stream();
  const Interface& I = model_.interface();
  const Layout& L = I.layout;
  const bool solid = model_.mesh().dim == 3;
  // "node": the contact node (pair) index of messages and history.csv; "mesh node": its point
  // in the mesh (the .vtu's point id), which a 3D run's pair order does not follow.
  std::vector<std::string> header = {"node", "mesh node", "x [mm]", "y [mm]"};
  if (solid) header.push_back("z [mm]");
  header.insert(header.end(), {model_.mesh().axisymmetric || solid ? "a [mm2]" : "a [mm]", "t [s]", "beta"});
  for (const char* q : {"u", "Rbar", "Radh", "r", "p"})
    for (const std::string& c : component_labels(L.dim))
      header.push_back(std::string(q) + "_" + c + (q[0] == 'u' ? " [mm]" : q[0] == 'p' ? " [MPa]" : " [N]"));
  header.push_back("status");
  header.push_back("interface");
  out << csv_line(header) << "\n";
  const Eigen::VectorXd Radh = b.r - s.Rbar;
  for (int i = 0; i < I.size(); ++i) {
    const Eigen::Vector3d& x = model_.mesh().nodes[I.pairs[i].node];
    const double a = I.pairs[i].measure;
    std::vector<std::string> row = {std::to_string(i), std::to_string(I.pairs[i].node)};
    for (double v : {x.x(), x.y()}) row.push_back(csv_number(v));
    if (solid) row.push_back(csv_number(x.z()));
    for (double v : {a, s.t, s.beta[i]}) row.push_back(csv_number(v));
    for (const Eigen::VectorXd* v : {&s.u, &s.Rbar, &Radh, &b.r})
      for (double value : normal_first(L, *v, i)) row.push_back(csv_number(value));
    for (double value : normal_first(L, b.r, i)) row.push_back(csv_number(value / a));
    row.push_back(status_name(s.status[i]));
    row.push_back(cfg_.interfaces[I.pairs[i].law].path);
    out << csv_line(row) << "\n";
  }
  file.commit();
  vtk_.write(s, b);
}

}  // namespace rccm

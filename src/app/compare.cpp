#include "rccm/app/compare.hpp"

#include "rccm/base/errors.hpp"
#include "rccm/base/format.hpp"
#include "rccm/contact/contact_solver.hpp"
#include "rccm/io/run_report.hpp"

#include <algorithm>
#include <cstdio>
#include <iterator>
#include <ostream>

namespace rccm {

namespace {

Method integrator_of(const std::string& name) {
  const Method methods[] = {Method::Arkode, Method::Euler, Method::RateIndependent, Method::ContactOnly};
  const Method* m =
      std::find_if(std::begin(methods), std::end(methods), [&](Method x) { return name == method_name(x); });
  if (m == std::end(methods))
    throw InputError("--integrators: unknown integrator '" + name + "' (arkode, euler, rate-independent, contact-only)");
  return *m;
}

ContactMethod solver_of(const std::string& name) {
  for (ContactMethod m : {ContactMethod::Bipotential, ContactMethod::Rccm, ContactMethod::Newton})
    if (name == contact_method_name(m)) return m;
  throw InputError("--solvers: unknown contact solver '" + name + "' (bipotential, rccm, newton)");
}

/// The paper's ratios of total CPU, RCCM (GYPTIS90) over bipotential (SYMEF): Tables 1 and 2.
const char* paper_ratios = "the paper: 161.7 s / 66.8 s = 2.4 on B1, 497.4 s / 136.5 s = 3.6 on B2";

/// Per integrator, the cases of each solver in the paper's layout: rows per solver, columns
/// the steps 1, 10, 40, 60, 100, 150, 200.
void print_tables(std::ostream& out, const std::vector<const CompareCase*>& cases) {
  std::vector<Method> integrators;
  for (const CompareCase* c : cases)
    if (std::find(integrators.begin(), integrators.end(), c->config.integrator.method) == integrators.end())
      integrators.push_back(c->config.integrator.method);
  for (Method m : integrators) {
    std::vector<const CompareCase*> group;
    for (const CompareCase* c : cases)
      if (c->config.integrator.method == m) group.push_back(c);
    out << "\n" << method_name(m);
    if (m != Method::Arkode)
      out << ", " << group.front()->config.time.steps << " fixed steps (and a step to each output time off them)";
    out << ": the paper's Tables 1-2 layout\n"
        << "(beta iterations: contact solves per step; contact iterations: sweeps or Newton steps per solve;\n"
        << "wall times, where the paper gives CPU times)\n";
    // The columns: steps every run reached (ARKODE's runs take their own numbers of steps).
    int last = 1 << 30;
    for (const CompareCase* c : group) last = std::min(last, static_cast<int>(c->result.steps.size()) - 1);
    char buf[64];
    std::snprintf(buf, sizeof buf, "%-34s", "step");
    out << buf;
    for (const PaperColumn& col : paper_table_columns(group.front()->config, group.front()->result, last))
      out << fmt("%10.0f", col.step);
    out << "  total wall [s]\n";
    for (const CompareCase* c : group) {
      const std::vector<PaperColumn> own = paper_table_columns(c->config, c->result, last);
      const std::string solver = contact_method_name(c->config.solver.method);
      const auto row = [&](const std::string& label, auto value, const std::string& total) {
        std::snprintf(buf, sizeof buf, "%-34s", label.c_str());
        out << buf;
        for (const PaperColumn& col : own) out << value(*col.record);
        out << total << "\n";
      };
      row(solver + ": beta iterations", [](const StepRecord& s) { return fmt("%10.0f", s.contact_solves); }, "");
      row(solver + ": contact iterations", [](const StepRecord& s) { return fmt("%10.1f", s.sweeps_mean); }, "");
      row(solver + ": wall [s]", [](const StepRecord& s) { return fmt("%10.2e", s.wall_seconds); },
          fmt("%16.3f", c->result.wall_seconds));
    }
    for (const CompareCase* c : group) {
      if (c == group.front()) continue;
      const ContactMethod m = c->config.solver.method, first = group.front()->config.solver.method;
      out << "total wall " << contact_method_name(m) << " / " << contact_method_name(first) << ": "
          << fmt("%.2f", c->result.wall_seconds / std::max(group.front()->result.wall_seconds, 1e-9));
      // The paper compares the classical RCCM algorithm with the bipotential only.
      if (m == ContactMethod::Rccm && first == ContactMethod::Bipotential) out << " (" << paper_ratios << ")";
      out << "\n";
    }
  }
}

}  // namespace

std::vector<CompareCase> run_comparison(const Config& cfg, const std::vector<std::string>& integrators,
                                        const std::vector<std::string>& solvers, int euler_steps) {
  std::vector<CompareCase> cases;
  const std::vector<std::string> solver_names =
      solvers.empty() ? std::vector<std::string>{contact_method_name(cfg.solver.method)} : solvers;
  // alpha = 0 on every interface: the rate-independent limit in place of the viscous
  // integrators asked (as `run` and `sweep`: rate_independent_limit), run once.
  const bool limit = alpha_zero_everywhere(cfg);
  std::vector<std::string> integrator_names, limited;  // each once; at alpha = 0, the method that runs
  for (const std::string& name : integrators) {
    const std::string runs = limit ? method_name(rate_independent_limit(integrator_of(name))) : name;
    if (limit && runs == "rate-independent") limited.push_back(name);
    if (std::find(integrator_names.begin(), integrator_names.end(), runs) == integrator_names.end())
      integrator_names.push_back(runs);
  }
  if (!limited.empty() && limited != std::vector<std::string>{"rate-independent"})
    std::fprintf(stderr, "rccm: note: alpha = 0 on every interface: the rate-independent limit runs once for the "
                         "integrators asked (%s)\n", comma_list(limited).c_str());
  for (const std::string& name : integrator_names)
    for (const std::string& solver : solver_names) {
      CompareCase c{solvers.size() > 1 ? name + "/" + solver : name, cfg, {}, {}};
      c.config.integrator.method = integrator_of(name);
      c.config.solver.method = solver_of(solver);
      if (name == "euler" && euler_steps > 0) c.config.time.steps = euler_steps;
      const bool viscous = c.config.integrator.method == Method::Arkode || c.config.integrator.method == Method::Euler;
      for (const InterfaceParams& p : cfg.interfaces)
        if (viscous && !(p.alpha > 0))
          throw InputError(cfg.where(p.path + ".alpha") + ": must be > 0 for integrator '" + name + "'");
      cases.push_back(std::move(c));
    }
  for (CompareCase& c : cases) {
    try {
      c.result = Simulation(c.config).run();
    } catch (const SolveError& e) {  // a method that cannot take the problem is a result too
      c.failure = e.what();
    }
  }
  return cases;
}

void print_comparison(std::ostream& out, const std::vector<CompareCase>& all) {
  std::vector<const CompareCase*> cases;  // those that ran
  for (const CompareCase& c : all)
    if (c.failure.empty())
      cases.push_back(&c);
    else
      out << c.label << ": run failed: " << c.failure << "\n";
  if (cases.empty()) return;
  const CompareCase& first = *cases.front();
  const std::vector<int>& watched = first.result.watched;
  // Columns as wide as the longest case's label and two spaces (a label runs into none).
  int width = 20;
  for (const CompareCase* c : cases) width = std::max(width, static_cast<int>(c->label.size()) + 2);
  const auto right = [&](const std::string& text) {  // right-aligned in its column
    return std::string(std::max(0, width - static_cast<int>(text.size())), ' ') + text;
  };
  const auto cell = [&](const char* format, double v) { return right(fmt(format, v)); };
  std::vector<std::pair<std::string, std::string>> rows;  // label, cells: printed once the labels' width is known
  auto row = [&](const std::string& label, auto&& value_of) {
    std::string cells;
    for (const CompareCase* c : cases) cells += value_of(*c);
    rows.emplace_back(label, cells);
  };
  row("", [&](const CompareCase& c) { return right(c.label); });
  const std::vector<Snapshot>& ref = first.result.snapshots;
  for (std::size_t k = 0; k < ref.size(); ++k) {
    for (std::size_t w = 0; w < watched.size(); ++w)
      row("beta at " + first.config.output.watch[w].name + ", t = " + fmt("%g", ref[k].t),
          [&](const CompareCase& c) { return cell("%.6e", c.result.snapshots[k].beta[watched[w]]); });
    row("max |beta - " + first.label + "|, t = " + fmt("%g", ref[k].t), [&](const CompareCase& c) {
      return cell("%.3e", (c.result.snapshots[k].beta - ref[k].beta).cwiseAbs().maxCoeff());
    });
  }
  row("steps", [&](const CompareCase& c) { return cell("%.0f", c.result.integrator.steps); });
  row("rejected steps", [&](const CompareCase& c) { return cell("%.0f", c.result.integrator.rejected); });
  row("RHS evaluations", [&](const CompareCase& c) { return cell("%.0f", c.result.integrator.rhs_evaluations); });
  row("contact solves (with commits)", [&](const CompareCase& c) { return cell("%.0f", c.result.solves.contact_solves); });
  row("Newton / fixed-point iterations", [&](const CompareCase& c) { return cell("%.0f", c.result.integrator.newton_iterations); });
  row("contact iterations per solve", [&](const CompareCase& c) {
    return cell("%.2f", double(c.result.solves.sweeps) / std::max(1L, c.result.solves.contact_solves));
  });
  row("contact iterations, max", [&](const CompareCase& c) { return cell("%.0f", c.result.solves.max_sweeps); });
  row("wall time [s]", [&](const CompareCase& c) { return cell("%.3f", c.result.wall_seconds); });
  std::size_t label_width = 34;
  for (const auto& [label, cells] : rows) label_width = std::max(label_width, label.size() + 1);
  for (const auto& [label, cells] : rows) out << label << std::string(label_width - label.size(), ' ') << cells << "\n";
  print_tables(out, cases);
  for (const CompareCase* c : cases)
    for (const std::string& w : c->result.warnings) out << c->label << ": warning: " << w << "\n";
}

}  // namespace rccm

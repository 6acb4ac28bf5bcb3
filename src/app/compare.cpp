#include "rccm/app/compare.hpp"

#include "rccm/base/errors.hpp"

#include <algorithm>
#include <cstdio>
#include <iterator>
#include <ostream>

namespace rccm {

std::vector<CompareCase> run_comparison(const Config& cfg, const std::vector<std::string>& integrators,
                                        int euler_steps) {
  std::vector<CompareCase> cases;
  for (const std::string& name : integrators) {
    CompareCase c{name, cfg, {}};
    const Method methods[] = {Method::Arkode, Method::Euler, Method::RateIndependent, Method::ContactOnly};
    const Method* m = std::find_if(std::begin(methods), std::end(methods),
                                   [&](Method x) { return name == method_name(x); });
    if (m == std::end(methods))
      throw InputError("--integrators: unknown integrator '" + name + "' (arkode, euler, rate-independent, contact-only)");
    c.config.integrator.method = *m;
    if (name == "euler" && euler_steps > 0) c.config.time.steps = euler_steps;
    const bool viscous = *m == Method::Arkode || *m == Method::Euler;
    for (const InterfaceParams& p : cfg.interfaces)
      if (viscous && !(p.alpha > 0))
        throw InputError(cfg.where(p.path + ".alpha") + ": must be > 0 for integrator '" + name + "'");
    cases.push_back(std::move(c));
  }
  for (CompareCase& c : cases) c.result = Simulation(c.config).run();
  return cases;
}

void print_comparison(std::ostream& out, const std::vector<CompareCase>& cases) {
  const std::vector<int>& watched = cases.front().result.watched;
  char buf[256];
  auto row = [&](const std::string& label, auto&& cell) {
    std::snprintf(buf, sizeof buf, "%-34s", label.c_str());
    out << buf;
    for (const CompareCase& c : cases) out << cell(c);
    out << "\n";
  };
  auto fmt = [&](const char* f, double v) {
    std::snprintf(buf, sizeof buf, f, v);
    return std::string(buf);
  };
  row("", [&](const CompareCase& c) {
    std::snprintf(buf, sizeof buf, "%18s", c.label.c_str());
    return std::string(buf);
  });
  const std::vector<Snapshot>& ref = cases.front().result.snapshots;
  for (std::size_t k = 0; k < ref.size(); ++k) {
    for (std::size_t w = 0; w < watched.size(); ++w)
      row("beta at " + cases.front().config.output.watch[w].name + ", t = " + fmt("%g", ref[k].t),
          [&](const CompareCase& c) { return fmt("%18.6e", c.result.snapshots[k].beta[watched[w]]); });
    row("max |beta - " + cases.front().label + "|, t = " + fmt("%g", ref[k].t), [&](const CompareCase& c) {
      return fmt("%18.3e", (c.result.snapshots[k].beta - ref[k].beta).cwiseAbs().maxCoeff());
    });
  }
  row("steps", [&](const CompareCase& c) { return fmt("%18.0f", c.result.integrator.steps); });
  row("rejected steps", [&](const CompareCase& c) { return fmt("%18.0f", c.result.integrator.rejected); });
  row("RHS evaluations", [&](const CompareCase& c) { return fmt("%18.0f", c.result.integrator.rhs_evaluations); });
  row("contact solves (with commits)", [&](const CompareCase& c) { return fmt("%18.0f", c.result.solves.contact_solves); });
  row("Newton / fixed-point iterations", [&](const CompareCase& c) { return fmt("%18.0f", c.result.integrator.newton_iterations); });
  row("bipotential sweeps per solve", [&](const CompareCase& c) {
    return fmt("%18.2f", double(c.result.solves.sweeps) / std::max(1L, c.result.solves.contact_solves));
  });
  row("bipotential sweeps, max", [&](const CompareCase& c) { return fmt("%18.0f", c.result.solves.max_sweeps); });
  row("wall time [s]", [&](const CompareCase& c) { return fmt("%18.3f", c.result.wall_seconds); });
  for (const CompareCase& c : cases)
    for (const std::string& w : c.result.warnings) out << c.label << ": warning: " << w << "\n";
}

}  // namespace rccm

// Verification (docs/VERIFICATION.md): energy balance, exact rate-independent results, symmetry
// and invariance under a change of units.
#include "helpers.hpp"
#include "rccm/model/model.hpp"
#include "rccm/app/simulation.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

using namespace rccm;

namespace {

using test::shipped;

double energy_error(const std::string& file, const std::string& rtol) {
  return Simulation(load_config(shipped(file), {"integrator.rtol=" + rtol, "integrator.atol=1e-14"}))
      .run()
      .energy.relative_error();
}

}  // namespace

TEST_CASE("energy balance of B1 and B2 closes, and better as the tolerance tightens", "[verification]") {
  // The terms are trapezoid sums over the accepted steps: the imbalance shrinks as the
  // tolerance tightens and the steps shorten.
  const double b1_4 = energy_error("b1.cfg", "1e-4"), b1_6 = energy_error("b1.cfg", "1e-6"),
               b1_8 = energy_error("b1.cfg", "1e-8");
  INFO("B1 relative imbalance at rtol 1e-4, 1e-6, 1e-8: " << b1_4 << " " << b1_6 << " " << b1_8);
  CHECK(b1_6 < b1_4);
  CHECK(b1_8 < b1_6);
  CHECK(b1_8 < 1e-4);
  const double b2_4 = energy_error("b2.cfg", "1e-4"), b2_6 = energy_error("b2.cfg", "1e-6");
  INFO("B2 relative imbalance at rtol 1e-4, 1e-6: " << b2_4 << " " << b2_6);
  CHECK(b2_6 < b2_4);
  CHECK(b2_6 < 1e-6);
}

TEST_CASE("rate-independent single node: peak force sqrt(C w) at u0 = sqrt(w/C), work w to full debonding",
          "[verification]") {
  // Every contact node prescribed to open by u = v t (the body translates rigidly), C = 1e3,
  // w = 1e-3: u0 = 1e-3 mm at t0 = 0.01 s; opened to 100 u0 by T = 1 s.
  const double C = 1e3, w = 1e-3, L = 4.0, u0 = std::sqrt(w / C), umax = 0.1;
  const std::string text = R"(
mesh = { size = [4.0, 1.0]; nx = 4; ny = 1; };
material = { E = 1000.0; nu = 0.3; };
interface = { boundary = "bottom"; Cn = 1000.0; Ct = 1000.0; w = 0.001; alpha = 0.0; mu = 0.2; };
loads = ( { node_set = "bottom"; type = "displacement"; component = "x"; value = 0.0; },
          { node_set = "bottom"; type = "displacement"; component = "y"; value = 0.1; } );
time = { T = 1.0; steps = 4000; };
output = { times = [0.01]; };
integrator = { method = "rate-independent"; };
)";
  const RunResult r = Simulation(test::config_from_text(text)).run();
  // The holding force is the resultant on the prescribed y DOFs: peak a sqrt(C w) per unit length.
  CHECK(std::abs(r.peak_force[1]) == Approx(L * std::sqrt(C * w)).epsilon(1e-10));
  CHECK(r.peak_time[1] == Approx(u0 / umax).epsilon(1e-10));
  // Work to (nearly) full debonding: w per unit area, less the tail w (u0/umax)^2 / 2 beyond umax.
  const double exact = w * L * (1 - 0.5 * (u0 / umax) * (u0 / umax));
  CHECK(r.energy.external_work == Approx(exact).epsilon(2e-4));
}

TEST_CASE("a symmetric problem gives symmetric beta and reactions", "[verification]") {
  // Q4 block (the T3 diagonal is not mirror symmetric), its top middle node pulled up.
  const std::string text = R"(
mesh = { size = [20.0, 4.0]; nx = 16; ny = 4; element = "Q4";
         node_sets = ( { name = "mid"; box = [10.0, 10.0, 4.0, 4.0]; } ); };
material = { E = 70000.0; nu = 0.3; };
interface = { boundary = "bottom"; Cn = 1000.0; Ct = 1000.0; w = 0.001; alpha = 1.0; mu = 0.3; };
loads = ( { node_set = "mid"; type = "displacement"; component = "y"; value = 0.1; } );
time = { T = 2.0; };
output = { times = [1.0]; };
)";
  const RunResult r = Simulation(test::config_from_text(text)).run();
  for (const Snapshot& s : r.snapshots) {
    const int n = static_cast<int>(s.beta.size());
    if (s.t == r.snapshots.back().t) REQUIRE(s.beta.minCoeff() < 0.5);  // damage happened
    const double F = s.Rbar.cwiseAbs().maxCoeff() + 1e-300, U = s.u.cwiseAbs().maxCoeff();
    for (int i = 0; i < n; ++i) {
      const int j = n - 1 - i;  // mirror node
      INFO("t " << s.t << " node " << i);
      CHECK(s.beta[i] == Approx(s.beta[j]).margin(1e-7));
      CHECK(s.u[2 * i + 1] == Approx(s.u[2 * j + 1]).margin(1e-8 * U));   // u_n symmetric
      CHECK(s.u[2 * i] == Approx(-s.u[2 * j]).margin(1e-8 * U));          // u_t antisymmetric
      CHECK(s.Rbar[2 * i + 1] == Approx(s.Rbar[2 * j + 1]).margin(1e-7 * F));
      CHECK(s.Rbar[2 * i] == Approx(-s.Rbar[2 * j]).margin(1e-7 * F));
    }
  }
}

TEST_CASE("changing units consistently (mm, N, MPa to m, N, Pa) gives the same dimensionless results",
          "[verification]") {
  // Lengths x 1e-3, stresses x 1e6, C (N/mm^3) x 1e9, w (N/mm) x 1e3, alpha (N s/mm) x 1e3;
  // plane forces are per unit thickness (N/mm -> N/m: x 1e3); beta and time unchanged.
  const std::vector<std::string> metres = {
      "mesh.size=[0.05,0.0025]",          "material.E=6.9e10",          "interface.Cn=2e14",
      "interface.Ct=2e14",                "interface.w=1e-3",           "interface.alpha=1e3",
      "output.watch=({name=\"B\";point=[0.0,0.0];})"};
  // A fixed step: both runs take the same steps, so they must agree to round-off (with
  // adaptive steps a step-size decision flipped by round-off moves the front node's beta by
  // the run's global error, ~4e-6 at rtol 1e-8 against a run at rtol 1e-10).
  std::vector<std::string> mm_set = {"time.T=2.0", "output.times=[1.0]", "integrator.fixed_step=0.002"};
  std::vector<std::string> m_set = mm_set;
  m_set.insert(m_set.end(), metres.begin(), metres.end());
  const RunResult mm = Simulation(load_config(shipped("b1.cfg"), mm_set)).run();
  // The pull of A is 0.3 mm over 10 s: in metres, 3e-4 m; written through a table to keep T = 2.
  const std::string b1m = shipped("b1.cfg");
  Config cfg_m = load_config(b1m, m_set);
  for (double& v : cfg_m.loads[0].amplitude.v) v *= 1e-3;
  const RunResult m = Simulation(cfg_m).run();
  for (std::size_t k = 0; k < mm.snapshots.size(); ++k) {
    INFO("t = " << mm.snapshots[k].t);
    CHECK((mm.snapshots[k].beta - m.snapshots[k].beta).cwiseAbs().maxCoeff() <= 1e-8);
    CHECK((1e-3 * mm.snapshots[k].u - m.snapshots[k].u).cwiseAbs().maxCoeff() <=
          1e-8 * 1e-3 * mm.snapshots[k].u.cwiseAbs().maxCoeff());
  }
  CHECK(m.peak_force[0] == Approx(1e3 * mm.peak_force[0]).epsilon(1e-8));
}

namespace {

/// Plane Hertz contact, frictionless and without adhesion (beta = 0): an elastic block
/// pressed onto the rigid foundation through the gap g0(x) = x^2 / (2 R) of a cylinder of
/// radius R. Half model (x >= 0, u_x = 0 on the symmetry line), traction q on the top,
/// n cells per unit length. Returns the relative L2 error of the contact pressure against
///   p(x) = p0 sqrt(1 - x^2 / a^2),  a^2 = 4 P R / (pi E*),  p0 = 2 P / (pi a),  E* = E / (1 - nu^2),
/// with P = 2 q L the force of the whole cylinder; the block is 10 a wide and 10 a high.
struct Hertz {
  double l2_error = 0, force = 0, exact_force = 0, contact_half_width = 0, h = 0;
};

Hertz hertz(int n) {
  const double a = 1.0, R = 100.0, E = 1000.0, nu = 0.3, L = 10.0;
  const double Es = E / (1 - nu * nu), P = M_PI * Es * a * a / (4 * R), p0 = 2 * P / (M_PI * a), q = P / (2 * L);
  const double h = 1.0 / n;
  std::ostringstream g0;
  g0 << std::scientific << std::setprecision(17);
  for (int i = 0; i <= 2 * n; ++i) g0 << (i ? ", " : "") << (i * h) * (i * h) / (2 * R);
  std::ostringstream text;
  text << std::setprecision(17);
  text << "mesh = { size = [" << L << ", " << L << "]; nx = " << n * 10 << "; ny = " << n * 10 << R"(; element = "Q4";
  node_sets = ( { name = "contact"; box = [0.0, 2.0, 0.0, 0.0]; } ); };
material = { E = 1000.0; nu = 0.3; };
interface = { boundary = "contact"; Cn = 1000.0; Ct = 1000.0; w = 0.0; mu = 0.0; beta0 = 0.0; g0 = [)"
       << g0.str() << R"(]; };
loads = ( { node_set = "left"; type = "displacement"; component = "x"; value = 0.0; },
          { node_set = "top"; type = "traction"; component = "y"; value = )"
       << -q << R"(; } );
time = { T = 1.0; steps = 1; };
integrator = { method = "contact-only"; };
)";
  const Config cfg = test::config_from_text(text.str());
  const Model model = test::make_model(cfg);
  const Snapshot s = Simulation(cfg).run().snapshots.back();
  Hertz out;
  out.h = h;
  out.exact_force = P / 2;
  double num = 0, den = 0;
  for (int i = 0; i < model.contact_nodes(); ++i) {
    const double x = model.mesh().nodes[model.interface().pairs[i].node].x(), ai = model.interface().pairs[i].measure;
    const double p = s.Rbar[2 * i + 1] / ai, exact = p0 * std::sqrt(std::max(0.0, 1 - x * x / (a * a)));
    num += ai * (p - exact) * (p - exact);
    den += ai * exact * exact;
    out.force += s.Rbar[2 * i + 1];
    if (p > 0) out.contact_half_width = std::max(out.contact_half_width, x);
  }
  out.l2_error = std::sqrt(num / den);
  return out;
}

}  // namespace

TEST_CASE("Hertz contact: the pressure converges to the analytical one under mesh refinement", "[verification]") {
  std::cout << "Hertz: h/a  relative L2 error of the pressure  observed order  contact half-width/a\n";
  std::vector<Hertz> runs;
  for (int n : {4, 8, 16}) {
    runs.push_back(hertz(n));
    const Hertz& r = runs.back();
    const double order = runs.size() > 1 ? std::log2(runs[runs.size() - 2].l2_error / r.l2_error) : 0.0;
    std::cout << r.h << "  " << r.l2_error << "  " << order << "  " << r.contact_half_width << "\n";
    INFO("h/a = " << r.h << ": L2 error " << r.l2_error << ", half-width " << r.contact_half_width);
    CHECK(r.force == Approx(r.exact_force).epsilon(1e-9));              // equilibrium with the load
    CHECK(std::abs(r.contact_half_width - 1.0) <= r.h + 1e-12);        // a to within one cell
    if (runs.size() > 1) CHECK(order > 0.6);                             // first order, less the edge
  }
  CHECK(runs.back().l2_error < 0.04);
}

TEST_CASE("rotating the whole problem and the foundation normal leaves the interface quantities unchanged",
          "[verification]") {
  // B1 with A's displacement prescribed in both components, v(t) n: a load that turns with the body.
  const auto rotated = [&](double degrees) {
    const double c = std::cos(degrees * M_PI / 180), s = std::sin(degrees * M_PI / 180);
    std::ostringstream n, loads;
    n << std::setprecision(17) << std::showpoint << "interface.normal=[" << -s << ", " << c << "]";
    loads << std::setprecision(17) << std::showpoint << "loads=({node_set=\"top_left\"; type=\"displacement\"; component=\"x\"; value="
          << -0.06 * s << ";}, {node_set=\"top_left\"; type=\"displacement\"; component=\"y\"; value=" << 0.06 * c
          << ";})";
    return Simulation(load_config(shipped("b1.cfg"), {"mesh.rotation=" + std::to_string(degrees), n.str(),
                                                      loads.str(), "time.T=2.0", "output.times=[1.0]"}))
        .run();
  };
  const RunResult r0 = rotated(0.0);
  REQUIRE(r0.snapshots.back().beta.minCoeff() < 0.5);  // a debonding front has formed
  for (double degrees : {30.0, 90.0, 217.0}) {
    const RunResult r = rotated(degrees);
    REQUIRE(r.snapshots.size() == r0.snapshots.size());
    for (std::size_t k = 0; k < r.snapshots.size(); ++k) {
      const Snapshot &a = r0.snapshots[k], &b = r.snapshots[k];
      INFO("rotation " << degrees << " degrees, t = " << a.t);
      std::cout << "rotation " << degrees << " t " << a.t << ": max |dbeta| " << (a.beta - b.beta).cwiseAbs().maxCoeff()
                << ", max |dRbar|/max|Rbar| "
                << (a.Rbar - b.Rbar).cwiseAbs().maxCoeff() / a.Rbar.cwiseAbs().maxCoeff() << "\n";
      CHECK((a.beta - b.beta).cwiseAbs().maxCoeff() <= 1e-10);
      CHECK((a.u - b.u).cwiseAbs().maxCoeff() <= 1e-10 * a.u.cwiseAbs().maxCoeff());
      CHECK((a.Rbar - b.Rbar).cwiseAbs().maxCoeff() <= 1e-10 * a.Rbar.cwiseAbs().maxCoeff());
    }
    CHECK(r.energy.external_work == Approx(r0.energy.external_work).epsilon(1e-6));
  }
}

TEST_CASE("B1 under mesh refinement: beta along the interface at t1 converges", "[.refinement][verification]") {
  // Meshes 32 x 2 to 256 x 16 (k = 1, 2, 4, 8): beta at the coarse nodes, compared between
  // successive meshes in the L1 norm along the interface, and the debonded length.
  struct Level {
    std::map<long, double> beta;  // by x in nm: the coarse nodes exist on every mesh
    double debonded = 0;
  };
  std::vector<Level> levels;
  for (int k : {1, 2, 4, 8}) {
    const Config cfg = load_config(shipped("b1.cfg"), {"mesh.nx=" + std::to_string(32 * k),
                                                       "mesh.ny=" + std::to_string(2 * k), "time.T=3.571",
                                                       "output.times=[3.571]"});
    const Model model = test::make_model(cfg);
    const Snapshot s = Simulation(cfg).run().snapshots.back();
    Level l;
    for (int i = 0; i < model.contact_nodes(); ++i)
      l.beta[std::lround(1e6 * model.mesh().nodes[model.interface().pairs[i].node].x())] = s.beta[i];
    l.debonded = s.debonded_length;
    levels.push_back(l);
  }
  std::vector<double> l1, front;
  for (std::size_t j = 0; j + 1 < levels.size(); ++j) {
    double e = 0;
    for (const auto& [x, b] : levels[0].beta) e += std::abs(levels[j].beta.at(x) - levels[j + 1].beta.at(x));
    l1.push_back(e / levels[0].beta.size());
    front.push_back(std::abs(levels[j].debonded - levels[j + 1].debonded));
  }
  std::cout << "B1 refinement at t1 (k = 1, 2, 4, 8): debonded length [mm], mean |beta_h - beta_h/2|, orders\n";
  for (std::size_t j = 0; j < levels.size(); ++j) {
    std::cout << "k " << (1 << j) << ": debonded " << levels[j].debonded;
    if (j < l1.size()) std::cout << ", mean |beta_h - beta_h/2| " << l1[j] << ", |length difference| " << front[j];
    if (j > 0 && j < l1.size())
      std::cout << ", orders " << std::log2(l1[j - 1] / l1[j]) << " (beta), " << std::log2(front[j - 1] / front[j])
                << " (length)";
    std::cout << "\n";
  }
  for (std::size_t j = 1; j < l1.size(); ++j) {
    CHECK(l1[j] < 0.75 * l1[j - 1]);
    CHECK(front[j] < 0.75 * front[j - 1]);
  }
}

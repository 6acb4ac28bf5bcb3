// Verification (VERIFICATION.md): energy balance, exact rate-independent results, symmetry
// and invariance under a change of units.
#include "helpers.hpp"
#include "rccm/simulation.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace rccm;

namespace {

std::string shipped(const std::string& name) { return std::string(RCCM_SOURCE_DIR) + "/config/" + name; }

double energy_error(const std::string& file, const std::string& rtol) {
  return Simulation(load_config(shipped(file), {"integrator.rtol=" + rtol, "integrator.atol=1e-14"}))
      .run()
      .energy.relative_error();
}

}  // namespace

TEST_CASE("energy balance of B1 and B2 closes, and better as the tolerance tightens", "[verification]") {
  const double b1_4 = energy_error("b1.cfg", "1e-4"), b1_6 = energy_error("b1.cfg", "1e-6"),
               b1_7 = energy_error("b1.cfg", "1e-7");
  INFO("B1 relative imbalance at rtol 1e-4, 1e-6, 1e-7: " << b1_4 << " " << b1_6 << " " << b1_7);
  CHECK(b1_6 < b1_4);
  CHECK(b1_7 < b1_6);
  CHECK(b1_7 < 1e-4);
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
  std::vector<std::string> mm_set = {"time.T=2.0", "output.times=[1.0]"};
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
    CHECK((mm.snapshots[k].beta - m.snapshots[k].beta).cwiseAbs().maxCoeff() <= 1e-6);
    CHECK((1e-3 * mm.snapshots[k].u - m.snapshots[k].u).cwiseAbs().maxCoeff() <=
          1e-6 * 1e-3 * mm.snapshots[k].u.cwiseAbs().maxCoeff());
  }
  CHECK(m.peak_force[0] == Approx(1e3 * mm.peak_force[0]).epsilon(1e-6));
}

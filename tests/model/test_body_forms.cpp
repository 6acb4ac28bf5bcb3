// The bulk's figures of a step from the body forms (model/body_forms, no solve of the body)
// against the same figures from the full displacement (one solve): each load's resultant and
// displacement, the probes, the loads' work pairs and the strain energy, in the plane, on an
// axisymmetric mesh and in 3D; the work pairs' identity f_ext(X).u(Y) = dot(X, Y) on the full
// vectors; and all of it unchanged when K0 is condensed anew with its springs elsewhere.
#include "helpers.hpp"
#include "rccm/app/simulation.hpp"
#include "rccm/model/body_state.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace rccm;

namespace {

/// A block bonded by its base, held at x = 0 on the left, pulled up on its top (whose
/// corner node over the right edge takes a share on a DOF the lift moves), pressed on its right
/// and lifted there by a table.
Config block(const std::string& mesh, const std::string& hypothesis, const std::string& lift_component) {
  const bool solid = hypothesis.empty();
  const std::string z = solid ? ", 0.5" : "";
  return test::config_from_text(mesh + R"(
material = { E = 1000.0; nu = 0.3; )" + (solid ? "" : "hypothesis = \"" + hypothesis + "\";") + R"( };
interface = { boundary = "bottom"; Cn = 500.0; Ct = 300.0; w = 2.0e-4; alpha = 0.1; mu = 0.3; };
loads = ( { node_set = "left"; type = "displacement"; component = "x"; value = 0.0; },
          { node_set = "top"; type = "traction"; component = "y"; value = 0.05; },
          { node_set = "right"; type = "pressure"; value = 0.01; },
          { node_set = "right"; type = "displacement"; component = ")" + lift_component + R"("; table = ( (0.0, 0.0), (1.0, 0.02) ); } );
time = { T = 1.0; };
solver = { springs_follow_beta = false; };
output = { probes = ( { name = "middle"; point = [2.0, 1.0)" + z + R"(]; }, { name = "corner"; point = [4.0, 2.0)" + z + R"(]; } ); };
)");
}

double largest(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

void check_close(const std::vector<double>& a, const std::vector<double>& b, double scale, const char* what) {
  REQUIRE(a.size() == b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    INFO(what << " " << k << ": " << a[k] << " against " << b[k]);
    CHECK(std::abs(a[k] - b[k]) <= 1e-9 * scale);
  }
}

std::vector<double> values(const Eigen::VectorXd& v) { return {v.data(), v.data() + v.size()}; }

/// The resultants of s against its full body state; returns the number of figures compared.
int compare(const Model& model, const InterfaceState& s, const BodyState& full) {
  const BodyState b = body_resultants(model, s);
  CHECK(b.u.size() == 0);  // no solve of the body
  const double force = std::max(largest(full.force), 1e-12), length = std::max(largest(full.probes), 1e-12);
  check_close(b.force, full.force, force, "force of load");
  check_close(b.displacement, full.displacement, std::max(largest(full.displacement), 1e-12), "displacement of load");
  check_close(b.probes, full.probes, length, "probe component");
  check_close(values(b.work.a), values(full.work.a), 1.0, "amplitude");
  check_close(values(b.work.phi), values(full.work.phi), std::max(largest(values(full.work.phi)), 1e-12), "phi");
  check_close(values(b.work.rho), values(full.work.rho), std::max(largest(values(full.work.rho)), 1e-12), "rho");
  CHECK(b.strain_energy == Approx(full.strain_energy).epsilon(1e-9));
  return int(b.force.size() + b.displacement.size() + b.probes.size() + 3 * b.work.a.size() + 1);
}

}  // namespace

TEST_CASE("the step's resultants from the body forms equal those of the full displacement", "[forms]") {
  const std::string plane = R"(mesh = { size = [4.0, 2.0]; nx = 8; ny = 4; element = "Q4"; };)";
  const std::string ring = R"(mesh = { origin = [1.0, 0.0]; size = [4.0, 2.0]; nx = 8; ny = 4; element = "Q4"; };)";
  const std::string solid = R"(mesh = { size = [4.0, 2.0, 1.0]; nx = 4; ny = 2; nz = 1; element = "H8"; };)";
  for (const auto& [mesh, hypothesis, lift] : {std::tuple{plane, "plane_strain", "y"},
                                               std::tuple{ring, "axisymmetric", "y"},
                                               std::tuple{solid, "", "y"}}) {
    INFO(mesh);
    const Config cfg = block(mesh, hypothesis, lift);
    const Model model = test::make_model(cfg);
    REQUIRE(model.probes().size() == 2);
    int figures = 0, steps = 0, midpoints = 0;
    double work_identity = 0, strain_peak = 0;
    RunOptions o;
    o.observer = [&](const AcceptedStep& a) {
      const BodyState full = body_state(model, a.state);
      figures += compare(model, a.state, full);
      ++steps;
      strain_peak = std::max(strain_peak, full.strain_energy);
      // f_ext(X) . u(Y) = dot(X, Y) on the full vectors, also between two states.
      const double scale = std::max(std::abs(full.f_ext.dot(full.u)), 1e-30);
      work_identity = std::max(work_identity, std::abs(dot(full.work, full.work) - full.f_ext.dot(full.u)) / scale);
      if (!a.midpoint) return;
      const BodyState mid = body_state(model, *a.midpoint);
      figures += compare(model, *a.midpoint, mid);
      ++midpoints;
      work_identity = std::max(work_identity, std::abs(dot(full.work, mid.work) - full.f_ext.dot(mid.u)) / scale);
      work_identity = std::max(work_identity, std::abs(dot(mid.work, full.work) - mid.f_ext.dot(full.u)) / scale);
    };
    const RunResult r = Simulation(cfg, o).run();
    REQUIRE(r.stopped.empty());
    CHECK(steps > 10);
    CHECK(midpoints > 10);
    CHECK(figures > 20 * steps);
    CHECK(strain_peak > 1e-6);  // loaded: the figures are not all zero
    CHECK(work_identity < 1e-9);
  }
}

TEST_CASE("the body forms condensed anew with K0's springs elsewhere give the same resultants", "[forms]") {
  const Config cfg = block(R"(mesh = { size = [4.0, 2.0]; nx = 8; ny = 4; element = "Q4"; };)", "plane_strain", "y");
  Model model = test::make_model(cfg);
  InterfaceState last;
  RunOptions o;
  o.observer = [&](const AcceptedStep& a) { last = a.state; };
  REQUIRE(Simulation(cfg, o).run().stopped.empty());
  const BodyState before = body_state(model, last);
  REQUIRE(last.beta.minCoeff() < 0.9);  // debonding began: the springs below matter
  Eigen::VectorXd springs = last.beta;
  for (int i = 0; i < springs.size(); ++i) springs[i] = i % 2 ? 0.3 : 1.0;
  model.condense(springs);
  // The state split for the new springs (docs/MODEL.md s4): y = Rbar + (Dref - D(beta)) u.
  const ContactProblem pb = model.contact_problem(last.t, last.beta, last.u);
  InterfaceState s = last;
  s.y = s.Rbar + (pb.Dref - pb.Dbeta).cwiseProduct(s.u);
  REQUIRE((s.y - last.y).norm() > 1e-3 * last.y.norm());
  compare(model, s, before);
  compare(model, s, body_state(model, s));
}

// Siconos numerics as an independent peer for the contact step (built when Siconos is found).
#include "helpers.hpp"
#include "rccm/contact/contact_solver.hpp"
#include "rccm/base/config.hpp"
#include "rccm/model/interface_state.hpp"
#include "rccm/app/simulation.hpp"
#include "siconos_peer.hpp"

#include <catch2/catch.hpp>

#include <fstream>

using namespace rccm;

namespace {
SolverParams tight(ContactMethod method = ContactMethod::Bipotential) {
  SolverParams p;
  p.tolerance = 1e-12;
  p.max_iterations = 20000;
  p.method = method;
  return p;
}

constexpr ContactMethod methods[] = {ContactMethod::Bipotential, ContactMethod::Rccm, ContactMethod::Newton};

/// The folder of Siconos' test problems (shared/ beside the checkout), or "" with a warning.
std::string siconos_data() {
  const std::string dir = std::string(RCCM_SOURCE_DIR) + "/../shared/data/siconos-fc2d/";
  if (std::ifstream(dir + "README.md")) return dir;
  WARN("not checked: " << dir << " is missing (the shared/ folder lives beside the checkout)");
  return "";
}
}  // namespace

TEST_CASE("Siconos test problems: where Siconos NSGS converges, so do our solvers, and Newton also where it does not",
          "[peer]") {
  const std::string dir = siconos_data();
  if (dir.empty()) return;
  for (const char* f : {"FrictionContactProblem00394.dat", "FrictionContactProblem00031.dat",
                        "FrictionContactProblem00071.dat"}) {
    const PlainContactProblem p = peer::read_dat(dir + f);
    const peer::PeerSolution n = peer::solve(p, "nsgs", 1e-10, 100000);
    REQUIRE(n.info == 0);
    for (ContactMethod method : methods) {
      // rccm's projected Gauss-Seidel does not converge on 00071 in 1e5 sweeps (docs/PERFORMANCE.md).
      if (method == ContactMethod::Rccm && std::string(f) == "FrictionContactProblem00071.dat") continue;
      const ContactSolution s = make_contact_solver(tight(method))->solve(from_plain(p), {}, {});
      INFO(f << ", " << contact_method_name(method) << ": siconos error " << n.error << " in " << n.iterations
             << ", ours " << peer::error(p, s.Rbar) << " in " << s.iterations);
      CHECK(s.converged);
      CHECK(peer::error(p, s.Rbar) <= 1e-8);
      CHECK((s.Rbar - n.R).norm() <= 1e-6 * (1 + n.R.norm()));
    }
  }
  // The slider-crank problems (W singular, mu = 0.01): no Gauss-Seidel converges, Siconos'
  // included; Newton does, by Siconos' own error measure.
  for (const char* f : {"FC2D_SliderCrankLagrangian00000.dat", "FC2D_SliderCrankLagrangian00001.dat"}) {
    const PlainContactProblem p = peer::read_dat(dir + f);
    const ContactSolution s = make_contact_solver(tight(ContactMethod::Newton))->solve(from_plain(p), {}, {});
    INFO(f << ": Newton error " << peer::error(p, s.Rbar) << " in " << s.iterations);
    CHECK(s.converged);
    CHECK(peer::error(p, s.Rbar) <= 1e-12);
  }
}

TEST_CASE("Our plain Gauss-Seidel sweeps are Siconos' NSGS iterations: after each the same reactions",
          "[peer]") {
  // Without extrapolation or exact step, the bipotential solver's sweep on a plain problem
  // (2D: each pair's exact local solution, pairs in order, u updated after each) is the
  // algorithm of Siconos' fc2d NSGS: the k-th iterates agree to round-off long before either
  // converges. fc2d-bench's row "GS at Siconos' its" rests on it (the same work per solve).
  const std::string dir = siconos_data();
  if (dir.empty()) return;
  for (const char* f : {"FrictionContactProblem00071.dat", "fc2d_granularflowonwall_00667_00000.dat"}) {
    PlainContactProblem p = peer::read_dat(dir + f);  // 89 contacts dense; 667 sparse
    p.q /= p.q.norm();
    SolverParams params;
    params.tolerance = 1e-30;  // reached by no sweep: each solve makes exactly k
    params.anderson = 0;
    params.active_set = false;
    for (int k : {1, 2, 10, 40}) {
      params.max_iterations = k;
      const peer::PeerSolution n = peer::solve(p, "nsgs", 1e-30, k);
      const ContactSolution s = make_contact_solver(params)->solve(from_plain(p), {}, {});
      INFO(f << " after " << k << " iterations: siconos error " << n.error << ", ours " << peer::error(p, s.Rbar));
      REQUIRE(n.iterations == k);
      CHECK(s.iterations == k);
      CHECK(n.error > 1e-10);  // far from round-off: the iterates themselves are compared
      CHECK((s.Rbar - n.R).norm() <= 1e-12 * n.R.norm());
    }
  }
}

TEST_CASE("A large sparse Siconos problem stays sparse: Siconos' sparse NSGS and our bipotential solver agree",
          "[peer]") {
  const std::string dir = siconos_data();
  if (dir.empty()) return;
  const std::string file = dir + "fc2d_granularflowonwall_00667_00000.dat";
  PlainContactProblem p = peer::read_dat(file);  // 667 contacts, W stored sparse in the file
  REQUIRE(p.W->dense() == nullptr);
  // A snapshot at rest, |q| = 4e-18: scaled to |q| = 1 (the solution scales with q), where
  // Siconos' error measure is relative (below eps it is absolute and accepts R = 0).
  p.q /= p.q.norm();
  const peer::PeerSolution n = peer::solve(p, "nsgs", 1e-12, 100000);  // Siconos by 2x2 blocks
  REQUIRE(n.info == 0);
  const ContactSolution s = make_contact_solver(tight())->solve(from_plain(p), {}, {});
  INFO("siconos error " << n.error << " in " << n.iterations << ", ours " << peer::error(p, s.Rbar) << " in "
                        << s.iterations);
  CHECK(s.converged);
  CHECK(peer::error(p, s.Rbar) <= 1e-12);
  CHECK((s.Rbar - n.R).norm() <= 1e-8 * n.R.norm());
}

TEST_CASE("B1, B2 and two-body (ENF) condensed problems: Siconos and each of our solvers give the same reactions",
          "[peer]") {
  // enf.cfg: two glued arms with a frictional precrack (a body-body interface), every 12th
  // step of a coarse run through the peak and the crack's run.
  for (const char* file : {"b1.cfg", "b2.cfg", "enf.cfg"}) {
    const bool enf = std::string(file) == "enf.cfg";
    const Config cfg = load_config(std::string(RCCM_SOURCE_DIR) + "/config/" + file,
                                   enf ? std::vector<std::string>{"mesh.parameters.dx=1.0", "time.steps=60"}
                                       : std::vector<std::string>{"integrator.method=euler"});
    const Model model = test::make_model(cfg);
    const std::vector<peer::StepProblem> problems = peer::step_problems(model, cfg, enf ? 12 : 40);
    CHECK(problems.size() >= 4);
    for (const peer::StepProblem& sp : problems) {
      const peer::PeerSolution n = peer::solve(sp.plain, "nsgs", 1e-14, 100000);
      for (ContactMethod method : methods) {
        const ContactSolution ours = make_contact_solver(tight(method))->solve(sp.problem, {}, {});
        const double scale = std::max(ours.Rbar.norm(), 1e-300);
        INFO(file << " step " << sp.step << ", " << contact_method_name(method) << ": siconos error " << n.error
                  << ", ours " << peer::error(sp.plain, ours.Rbar));
        CHECK(ours.converged);
        if (scale > 1e-6) CHECK((ours.Rbar - n.R).norm() <= 1e-8 * scale);
        CHECK(peer::error(sp.plain, ours.Rbar) <= 1e-9);
      }
    }
  }
}

TEST_CASE("Siconos fc3d on the corner peel's condensed 3D problems: its NSGS and semi-smooth Newton, and our "
          "solvers, give the same reactions",
          "[peer]") {
  // A plate lifted by one corner (6 x 1 x 6 H8, 49 contact pairs), as config/corner-peel.cfg: its
  // commit problems every 40 accepted steps, springs and previous slip folded into the plain
  // form (Siconos knows neither); some pairs bonded, some debonded, sliding in 2D directions.
  const Config cfg = test::corner_peel(6);
  const Model model = test::make_model(cfg);
  const std::vector<peer::StepProblem> steps = peer::step_problems(model, cfg, 40);
  REQUIRE(steps.size() >= 3);
  for (const peer::StepProblem& sp : steps) {
    REQUIRE(sp.plain.dim == 3);
    for (const char* siconos : {"nsgs", "nsn"}) {
      const peer::PeerSolution n = peer::solve(sp.plain, siconos, 1e-12, 100000);
      INFO("step " << sp.step << ", Siconos " << siconos << ": error " << n.error << " in " << n.iterations);
      REQUIRE(n.info == 0);
      REQUIRE(n.R.norm() > 0);  // a problem with contact forces, not the trivial one
      for (ContactMethod method : {ContactMethod::Bipotential, ContactMethod::Newton}) {
        const ContactSolution s = make_contact_solver(tight(method))->solve(from_plain(sp.plain), {}, {});
        INFO(contact_method_name(method) << ": error " << peer::error(sp.plain, s.Rbar) << " in " << s.iterations);
        CHECK(s.converged);
        CHECK(peer::error(sp.plain, s.Rbar) <= 1e-9);
        CHECK((s.Rbar - n.R).norm() <= 1e-8 * (1 + n.R.norm()));
      }
    }
  }
}

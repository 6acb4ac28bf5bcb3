// Distributed loads (fem/loads): consistent nodal forces of a pressure and a traction, in
// the plane and on an axisymmetric mesh, add up to the exact resultants, and a pressure
// pushes along the inward normal of a curved boundary.
#include "helpers.hpp"
#include "rccm/app/simulation.hpp"
#include "rccm/base/errors.hpp"
#include "rccm/model/body_state.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

using namespace rccm;
namespace fs = std::filesystem;

namespace {

Eigen::Vector2d resultant(const Model& m, const LoadCase& lc) {
  Eigen::Vector2d F = Eigen::Vector2d::Zero();
  for (int n = 0; n < m.mesh().num_nodes(); ++n) F += lc.force.segment<2>(m.mesh().dof(n, 0));
  return F;
}

}  // namespace

TEST_CASE("pressure and traction: resultants in the plane and on the rings of an axisymmetric mesh", "[loads]") {
  for (const char* hypothesis : {"plane_strain", "axisymmetric"}) {
    const bool axisymmetric = std::string(hypothesis) == "axisymmetric";
    // The block r in [1, 3], z in [0, 3]: a pressure 2 on its top and right, a traction 0.5 along x on its top.
    const Config cfg = test::config_from_text(std::string(R"(
mesh = { origin = [1.0, 0.0]; size = [2.0, 3.0]; nx = 5; ny = 4; element = "Q4"; };
material = { E = 1000.0; nu = 0.3; hypothesis = ")") + hypothesis + R"("; };
interface = { boundary = "bottom"; Cn = 50.0; Ct = 30.0; w = 0.01; mu = 0.3; };
loads = ( { node_set = "top"; type = "pressure"; value = 2.0; },
          { node_set = "right"; type = "pressure"; value = 2.0; },
          { node_set = "top"; type = "traction"; component = "x"; value = 0.5; } );
time = { T = 1.0; };
integrator = { method = "contact-only"; };
)");
    const Model m = test::make_model(cfg);
    INFO(hypothesis);
    // Load cases are per unit value (the amplitude scales them). Top: area pi (3^2 - 1^2) (or
    // its length 2), pushed down. Right: the cylinder 2 pi 3 * 3 (or its length 3), pushed
    // towards the axis.
    const double top = axisymmetric ? M_PI * 8 : 2.0, right = axisymmetric ? 2 * M_PI * 3 * 3 : 3.0;
    CHECK(resultant(m, m.loads()[0]).isApprox(Eigen::Vector2d(0, -top), 1e-12));
    CHECK(resultant(m, m.loads()[1]).isApprox(Eigen::Vector2d(-right, 0), 1e-12));
    CHECK(resultant(m, m.loads()[2]).isApprox(Eigen::Vector2d(top, 0), 1e-12));
    // Consistent forces on the rings: int N_a 2 pi r ds gives the outer end node of the top
    // the share 2 pi L (r_a + 2 r_b) / 6 of its edge (L = 0.4, r_a = 2.6, r_b = 3).
    const int corner = m.mesh().node_set("top_right")[0];
    const double share = axisymmetric ? 2 * M_PI * 0.4 * (2.6 + 2 * 3.0) / 6 : 0.2;
    CHECK(m.loads()[0].force[m.mesh().dof(corner, 1)] == Approx(-share));
    // The force of a pressure in curves.csv: its resultant along the inward normal, p times the area.
    RunOptions o;
    BodyState b;
    o.observer = [&](const AcceptedStep& a) { b = body_state(m, a.state); };
    Simulation(cfg, o).run();
    CHECK(b.force[0] == Approx(2.0 * top));
    CHECK(b.force[1] == Approx(2.0 * right));
  }
}

TEST_CASE("a pressure on a curved boundary acts along its inward normal: its resultant is p times the chord",
          "[loads]") {
  const fs::path dir = fs::temp_directory_path() / ("rccm_loads_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  // A half annulus 1 < r < 2, y >= 0; the pressure on the outer arc.
  std::ofstream(dir / "half_ring.geo") << R"(
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0, 0.2}; Point(3) = {2, 0, 0, 0.2}; Point(4) = {-2, 0, 0, 0.2}; Point(5) = {-1, 0, 0, 0.2};
Line(1) = {2, 3}; Circle(2) = {3, 1, 4}; Line(3) = {4, 5}; Circle(4) = {5, 1, 2};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Physical Surface("ring") = {1}; Physical Curve("outer") = {2}; Physical Curve("base") = {1, 3};
)";
  const Config cfg = test::config_from_text("mesh = { file = \"" + (dir / "half_ring.geo").string() + R"("; };
material = { E = 1000.0; nu = 0.3; };
interface = { boundary = "base"; Cn = 50.0; Ct = 30.0; w = 0.01; mu = 0.3; };
loads = ( { node_set = "outer"; type = "pressure"; value = 3.0; } );
time = { T = 1.0; };
)");
  const Model m = test::make_model(cfg);
  const LoadCase& lc = m.loads()[0];
  // The arc's chord from (2, 0) to (-2, 0): the resultant of a unit pressure over the
  // polygon is the chord turned, (0, -4), whatever the mesh.
  CHECK(resultant(m, lc).isApprox(Eigen::Vector2d(0, -4.0), 1e-12));
  for (int n : m.mesh().node_set("outer")) {
    if (m.mesh().nodes[n].y() == 0) continue;  // an end node: one edge's normal
    const Eigen::Vector2d f = lc.force.segment<2>(m.mesh().dof(n, 0)), x = m.mesh().nodes[n].head<2>();
    INFO("node at (" << x.x() << ", " << x.y() << ")");
    CHECK(f.dot(x) < 0);                                   // towards the centre
    CHECK(std::abs(f.x() * x.y() - f.y() * x.x()) <= 1e-3 * f.norm() * x.norm());  // radial, to the mesh's polygon
  }
  fs::remove_all(dir);
}

TEST_CASE("the axis of an axisymmetric mesh holds u_r = 0: a zero radial displacement there is the same run", "[loads]") {
  const std::string base = R"(
mesh = { size = [2.0, 4.0]; nx = 2; ny = 4; element = "Q4"; origin = [0.0, 0.0]; };
material = { E = 1000.0; nu = 0.25; hypothesis = "axisymmetric"; };
interface = { boundary = "bottom"; Cn = 1.0e4; Ct = 1.0e4; w = 10.0; mu = 0.3; };
time = { T = 1.0; steps = 4; };
integrator = { method = "euler"; };
)";
  const std::string pull = R"(loads = ( { node_set = "top"; type = "displacement"; component = "y"; value = 0.001; } );)";
  const std::string held = R"(loads = ( { node_set = "top"; type = "displacement"; component = "y"; value = 0.001; },
                                          { node_set = "left"; type = "displacement"; component = "x"; value = 0.0; } );)";
  const RunResult a = Simulation(test::config_from_text(base + pull)).run();
  const RunResult b = Simulation(test::config_from_text(base + held)).run();
  REQUIRE(a.snapshots.size() == b.snapshots.size());
  CHECK(b.snapshots.back().u == a.snapshots.back().u);
  CHECK(a.snapshots.back().u.cwiseAbs().maxCoeff() > 1e-5);  // the pull reached the interface
  // A nonzero one, or a force there, is refused (tests/hostile/axisymmetric_*_on_axis.cfg: the messages).
  CHECK_THROWS_AS(test::make_model(test::config_from_text(base + R"(loads = ( { node_set = "left"; type = "force"; component = "x"; value = 1.0; } );)")), InputError);
}

TEST_CASE("a load table past time.T (times in ms) is noted with what the run applies at T", "[loads]") {
  const std::string base = R"(
mesh = { size = [10.0, 2.0]; nx = 4; ny = 1; };
material = { E = 1000.0; nu = 0.3; };
interface = { boundary = "bottom"; Cn = 1.0e4; Ct = 1.0e4; w = 10.0; mu = 0.3; };
time = { T = 4.0; };
)";
  const Model ms = test::make_model(test::config_from_text(
      base + R"(loads = ( { node_set = "top"; type = "displacement"; component = "y"; table = ((0.0, 0.0), (2000.0, 0.5), (4000.0, 2.0)); } );)"));
  REQUIRE(ms.notes().size() == 1);
  CHECK_THAT(ms.notes()[0], Catch::Contains(":6: loads.[0].table: its times go to 4000 s, past time.T = 4 s: the run "
                                            "applies it up to T only (0.001 at T, 2 at its end)"));
  const Model s = test::make_model(test::config_from_text(
      base + R"(loads = ( { node_set = "top"; type = "displacement"; component = "y"; table = ((0.0, 0.0), (4.0, 0.5)); } );)"));
  CHECK(s.notes().empty());
}

TEST_CASE("two supports meeting at a corner hold it once if alike and are refused if not", "[loads]") {
  // left x = 0 and bottom x = 0 share the corner node 0: held once, by loads.[0]; each load's
  // resultant counts the corner's reaction (it lies in both sets). Different values there
  // (bottom x = 0.01) cannot both hold: refused, naming both loads and what to do.
  const auto config = [](const std::string& bottom_x) {
    return test::config_from_text(R"(
mesh = { size = [4.0, 2.0]; nx = 4; ny = 2; element = "Q4"; };
material = { E = 1000.0; nu = 0.3; };
interface = { boundary = "bottom"; Cn = 50.0; Ct = 30.0; w = 0.01; mu = 0.3; };
loads = ( { node_set = "left"; type = "displacement"; component = "x"; value = 0.0; },
          { node_set = "bottom"; type = "displacement"; component = "x"; )" + bottom_x + R"( },
          { node_set = "top"; type = "displacement"; component = "y"; value = 0.02; } );
time = { T = 1.0; };
)");
  };
  const Model m = test::make_model(config("value = 0.0;"));
  const int corner = m.mesh().node_set("bottom_left")[0];
  const std::vector<int> held = prescribed_dofs(m.loads());
  CHECK(std::count(held.begin(), held.end(), m.mesh().dof(corner, 0)) == 1);
  CHECK(std::count(m.loads()[0].prescribed.begin(), m.loads()[0].prescribed.end(), m.mesh().dof(corner, 0)) == 1);
  CHECK(std::count(m.loads()[1].dofs.begin(), m.loads()[1].dofs.end(), m.mesh().dof(corner, 0)) == 1);
  CHECK(m.loads()[1].prescribed.size() == 4);  // the bottom's 5 nodes but the corner
  // The same function written otherwise: alike too (a ramp to 0.01 at T and its table with a
  // point midway); a table that differs between its points is not.
  const auto with_ramp = [&](const std::string& bottom_x) {
    Config cfg = config(bottom_x);
    cfg.loads[0].amplitude = {{0.0, 1.0}, {0.0, 0.01}};
    return test::make_model(cfg);
  };
  CHECK_NOTHROW(with_ramp("table = ( (0.0, 0.0), (0.5, 0.005), (1.0, 0.01) );"));
  CHECK_THROWS_WITH(with_ramp("table = ( (0.0, 0.0), (0.5, 0.004), (1.0, 0.01) );"),
                    Catch::Contains("is already prescribed by loads.[0] to other values"));
  CHECK_THROWS_WITH(test::make_model(config("value = 0.01;")),
                    Catch::Contains("loads.[1].node_set: node 0 component x is already prescribed by loads.[0] to other values") &&
                        Catch::Contains("take it out of one of the node sets"));
}

TEST_CASE("a support whose DOFs an earlier one holds alike reports their reaction as its force", "[loads]") {
  // bottom_left x = 0 lies within left x = 0: every DOF of it is held by loads.[0], and its
  // force in curves.csv is still the reaction there (not 0, as an applied load's would be).
  const Config cfg = test::config_from_text(R"(
mesh = { size = [4.0, 2.0]; nx = 4; ny = 2; element = "Q4"; };
material = { E = 1000.0; nu = 0.3; };
interface = { boundary = "bottom"; Cn = 50.0; Ct = 30.0; w = 0.01; mu = 0.3; };
loads = ( { node_set = "left"; type = "displacement"; component = "x"; value = 0.0; },
          { node_set = "bottom_left"; type = "displacement"; component = "x"; value = 0.0; },
          { node_set = "right"; type = "displacement"; component = "x"; value = 0.02; } );
time = { T = 1.0; };
integrator = { method = "contact-only"; };
)");
  const Model m = test::make_model(cfg);
  REQUIRE(m.loads()[1].prescribed.empty());
  BodyState b;
  RunOptions o;
  o.observer = [&](const AcceptedStep& a) { b = body_state(m, a.state); };
  Simulation(cfg, o).run();
  const int corner = m.mesh().dof(m.mesh().node_set("bottom_left")[0], 0);
  CHECK(std::abs(b.f_ext[corner]) > 1e-3);
  CHECK(b.force[1] == Approx(b.f_ext[corner]).epsilon(1e-12));
}

// 3D: the box of H8 cells, its boundary quads, the 3D law, and the RCCM interface on a face:
// B1 extruded into a slab reproduces 2D B1 on Q4 cells; a square plate peeled by one corner
// debonds symmetrically about the diagonal along a curved front, with beta never rising.
#include "helpers.hpp"
#include "solid_checks.hpp"
#include "rccm/app/simulation.hpp"
#include "rccm/fem/box_mesh.hpp"
#include "rccm/fem/elasticity.hpp"
#include "rccm/fem/material.hpp"
#include "rccm/interface/foundation.hpp"

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <iomanip>
#include <map>
#include <sstream>

using namespace rccm;

namespace {

// B1 (docs/BENCHMARKS.md) on 32 x 2 cells, in 2D on Q4 and as a 1 mm slab of H8 held at
// u_z = 0 (plane strain), explicit Euler-210 (the material apart).
const char* const kB1 = R"(
interface = { boundary = "bottom"; Cn = 2.0e5; Ct = 2.0e5; w = 1.0e-6; alpha = 1.0; mu = 0.2; beta0 = 1.0; };
time = { T = 10.0; steps = 210; };
integrator = { method = "euler"; };
output = { times = [3.571, 5.143]; };
)";

}  // namespace

TEST_CASE("H8: rigid motions are free, a uniform strain is in equilibrium, the 3D law is Hooke's", "[solid]") {
  const Mesh m = make_box(test::box(3.0, 2.0, 1.5, 3, 2, 2));
  REQUIRE(m.dim == 3);
  CHECK(m.num_nodes() == 4 * 3 * 3);
  CHECK(test::check_rigid_motions_and_patch(m, 1000.0, 0.3) == 2);
}

TEST_CASE("the box's faces: outward normals, areas, consistent nodal weights", "[solid]") {
  const Mesh m = make_box(test::box(4.0, 2.0, 3.0, 4, 2, 3));
  const std::map<std::string, std::pair<Eigen::Vector3d, double>> faces = {
      {"left", {-Eigen::Vector3d::UnitX(), 6.0}}, {"right", {Eigen::Vector3d::UnitX(), 6.0}},
      {"bottom", {-Eigen::Vector3d::UnitY(), 12.0}}, {"top", {Eigen::Vector3d::UnitY(), 12.0}},
      {"back", {-Eigen::Vector3d::UnitZ(), 8.0}}, {"front", {Eigen::Vector3d::UnitZ(), 8.0}}};
  for (const auto& [name, normal_area] : faces) {
    const std::vector<int>& set = m.node_set(name);
    double total = 0;
    for (double a : m.tributary_measures(set, m.facets_of(name))) total += a;
    CHECK(total == Approx(normal_area.second).epsilon(1e-14));
    for (const Eigen::Vector3d& n : m.outward_normals(set, m.facets_of(name))) CHECK((n - normal_area.first).norm() <= 1e-14);
  }
  // A node inside the bottom face carries one cell's area (1 x 1 mm), an edge node half, a
  // vertex a quarter.
  const std::vector<double> a = m.tributary_measures(m.node_set("bottom"), m.facets_of("bottom"));
  const std::vector<int>& bottom = m.node_set("bottom");
  for (std::size_t k = 0; k < bottom.size(); ++k) {
    const Eigen::Vector3d x = m.nodes[bottom[k]];
    const int on_edges = (x.x() == 0 || x.x() == 4) + (x.z() == 0 || x.z() == 3);
    CHECK(a[k] == Approx(1.0 / (1 << on_edges)).epsilon(1e-14));
  }
  CHECK(m.node_set("top_left_back") == std::vector<int>{m.node_set("top_left").front()});
}

namespace {

/// A plane problem on Q4 cells (`common` + `mesh` + `loads`) against the same extruded into
/// a 1 mm slab of H8 (`nz = 1`) held at u_z = 0 (plane strain): the interface's fields
/// node by node to `tol` (of their scale), the debonded area, the external work.
void check_extruded(const std::string& common, const std::string& mesh, const std::string& loads, int nx,
                    double length, double tol, const std::vector<std::string>& slab_overrides = {}) {
  const Config plane = test::config_from_text(common + "mesh = { " + mesh + " element = \"Q4\"; };\nloads = ( " + loads + " );\n");
  std::string mesh3 = mesh;
  const auto size_end = mesh3.find("];");
  mesh3.insert(size_end, ", 1.0");  // size = [Lx, Ly] -> [Lx, Ly, 1.0]
  const Config slab = test::config_from_text(common + "mesh = { " + mesh3 + " nz = 1; element = \"H8\"; };\nloads = ( " + loads +
                                                 ", { node_set = \"all\"; type = \"displacement\"; component = \"z\"; value = 0.0; } );\n",
                                             slab_overrides);
  const RunResult r2 = Simulation(plane).run(), r3 = Simulation(slab).run();
  REQUIRE(r2.snapshots.size() == r3.snapshots.size());
  const Model m3 = test::make_model(slab);
  REQUIRE(m3.interface().layout.dim == 3);
  REQUIRE(m3.contact_nodes() == 2 * (nx + 1));
  for (std::size_t s = 0; s < r2.snapshots.size(); ++s) {
    const Snapshot &a = r2.snapshots[s], &b = r3.snapshots[s];
    const double u_scale = a.u.cwiseAbs().maxCoeff(), R_scale = a.Rbar.cwiseAbs().maxCoeff();
    REQUIRE(u_scale > 0.01);
    REQUIRE(R_scale > 0);
    for (int i = 0; i < m3.contact_nodes(); ++i) {
      const int i2 = static_cast<int>(std::lround(m3.mesh().nodes[m3.interface().pairs[i].node].x() / (length / nx)));
      CHECK(std::abs(b.beta[i] - a.beta[i2]) <= tol);
      CHECK(std::abs(b.u[3 * i] - a.u[2 * i2]) <= tol * u_scale);          // u_t1 = u_t
      CHECK(std::abs(b.u[3 * i + 1]) <= 1e-12 * u_scale);                  // u_t2 = u_z = 0
      CHECK(std::abs(b.u[3 * i + 2] - a.u[2 * i2 + 1]) <= tol * u_scale);  // u_n
      // Each of the two layers of nodes takes half the 1 mm of thickness the 2D force acts on.
      CHECK(std::abs(2 * b.Rbar[3 * i] - a.Rbar[2 * i2]) <= tol * R_scale);
      CHECK(std::abs(2 * b.Rbar[3 * i + 2] - a.Rbar[2 * i2 + 1]) <= tol * R_scale);
    }
    CHECK(b.debonded_length == Approx(a.debonded_length * 1.0).margin(1e-9));  // area (mm2) = length x 1 mm
  }
  CHECK(r3.energy.external_work == Approx(r2.energy.external_work).epsilon(tol));
}

}  // namespace

TEST_CASE("B1 extruded into a slab of H8 held at u_z = 0 reproduces B1 on Q4 cells, isotropic and orthotropic", "[solid]") {
  // B1's aluminium, and a carbon/epoxy ply with its fibres at 30 degrees from x in the plane
  // (the 3D body's G13, G23 do not enter a plane strain state about z).
  const std::string material = GENERATE(as<std::string>{}, "material = { E = 6.9e4; nu = 0.333; };",
                                        "material = { E1 = 1.4e5; E2 = 1.0e4; E3 = 1.0e4; nu12 = 0.3; nu13 = 0.3; "
                                        "nu23 = 0.45; G12 = 5.0e3; angle = 30.0; };");
  INFO(material);
  std::vector<std::string> overrides;
  if (material.find("E1") != std::string::npos) overrides = {"material.G13=5000.0", "material.G23=3400.0"};
  check_extruded(std::string(kB1) + material + "\n", "size = [50.0, 2.5]; nx = 32; ny = 2;",
                 R"({ node_set = "top_left"; type = "displacement"; component = "y"; value = 0.3; })", 32, 50.0, 1e-8, overrides);
}

TEST_CASE("B2 extruded into a slab of H8 held at u_z = 0 reproduces B2 on Q4 cells", "[solid]") {
  // config/b2.cfg on Q4 cells (its box node set selects every z of the slab), explicit Euler-210:
  // its steps amplify round-off (E changed by 1.4e-16 moves beta at T by 3.9e-7: `rccm run
  // config/b2.cfg --set mesh.element=\"Q4\" --set integrator.method=\"euler\"` with E = 69000.00000000001),
  // hence 1e-6; the slab differs from the plane by 2.4e-7.
  check_extruded(R"(
material = { E = 6.9e4; nu = 0.333; };
interface = { boundary = "bottom"; Cn = 1.64; Ct = 1.64; w = 1.0e-3; alpha = 1.0; mu = 0.2; beta0 = 1.0; };
time = { T = 10.0; steps = 210; };
integrator = { method = "euler"; };
solver = { tolerance = 1.0e-10; };
output = { times = [2.143, 3.143, 3.571]; };
)",
                 R"(size = [50.0, 25.0]; nx = 32; ny = 16; node_sets = ( { name = "left_above"; box = [0.0, 0.0, 0.001, 25.0]; } );)",
                 R"({ node_set = "left_above"; type = "displacement"; component = "x"; value = 20.0; },
          { node_set = "top"; type = "displacement"; component = "y"; value = -0.5; })",
                 32, 50.0, 1e-6);
}

TEST_CASE("a 3D interface lists its pairs in bisection order: every bisection of the pairs' range is a "
          "compact patch (the compressed W0's clusters), not a strip of rows",
          "[solid]") {
  const Model model = test::make_model(test::corner_peel(8));  // 9 x 9 contact nodes in x-z, listed row by row
  const auto node_of = [&](int i) -> const Eigen::Vector3d& { return model.mesh().nodes[model.interface().pairs[i].node]; };
  int patches = 0;
  const std::function<void(int, int)> bisect = [&](int begin, int end) {
    if (end - begin < 8) return;
    Eigen::Vector3d lo = node_of(begin), hi = lo;
    for (int i = begin; i < end; ++i) lo = lo.cwiseMin(node_of(i)), hi = hi.cwiseMax(node_of(i));
    const double nx = hi.x() - lo.x() + 1, nz = hi.z() - lo.z() + 1;  // nodes across, 1 mm apart
    INFO("pairs " << begin << " to " << end << ": " << nx << " x " << nz << " nodes");
    CHECK(std::max(nx, nz) <= 2 * std::min(nx, nz));
    CHECK(nx * nz <= 2 * (end - begin));
    ++patches;
    bisect(begin, begin + (end - begin) / 2);  // the HODLR's bisection
    bisect(begin + (end - begin) / 2, end);
  };
  bisect(0, model.contact_nodes());
  CHECK(patches == 15);
}

TEST_CASE("a message names a contact node by its pair index, its mesh node and its point: in 3D, where the "
          "pair order is not the mesh's",
          "[solid]") {
  const Model model = test::make_model(test::corner_peel(8));
  int reordered = 0;
  for (int i = 0; i < model.contact_nodes(); ++i) {
    const int n = model.interface().pairs[i].node;
    const Eigen::Vector3d& x = model.mesh().nodes[n];
    std::ostringstream want;
    want << "contact node " << i << " (mesh node " << n << " at (" << x.x() << ", " << x.y() << ", " << x.z() << "))";
    CHECK(model.locate(i) == want.str());
    reordered += n != model.interface().pairs[0].node + i;
  }
  CHECK(reordered > model.contact_nodes() / 2);  // the check above is not one of i alone
}

// The corner lifted 0.03 mm/s for 5 s, by sweeps (the 3D exact step costs more here: README).
TEST_CASE("a square plate peeled by one corner: symmetric about the diagonal, a curved front, beta never rises", "[solid]") {
  const Config cfg = test::corner_peel(8, {"output.times=[2.5]"});
  Eigen::VectorXd previous;
  bool rose = false;
  RunOptions options;
  options.observer = [&](const AcceptedStep& a) {
    if (previous.size() && (a.state.beta.array() > previous.array() + 1e-14).any()) rose = true;
    previous = a.state.beta;
  };
  const RunResult r = Simulation(cfg, options).run();
  CHECK_FALSE(rose);
  const Model model = test::make_model(cfg);
  std::map<std::pair<long, long>, int> at;  // (x, z) in mm -> pair
  for (int i = 0; i < model.contact_nodes(); ++i) {
    const Eigen::Vector3d x = model.mesh().nodes[model.interface().pairs[i].node];
    at[{std::lround(x.x()), std::lround(x.z())}] = i;
  }
  const Snapshot& end = r.snapshots.back();
  int debonded_off_axes = 0, debonded = 0;
  for (const auto& [xz, i] : at) {
    const int j = at.at({xz.second, xz.first});
    CHECK(std::abs(end.beta[i] - end.beta[j]) <= 1e-8);
    CHECK(std::abs(end.u[3 * i + 2] - end.u[3 * j + 2]) <= 1e-8 * end.u.cwiseAbs().maxCoeff());
    debonded += end.beta[i] < 0.5;
    debonded_off_axes += end.beta[i] < 0.5 && xz.first > 0 && xz.second > 0;
  }
  // Debonded around the corner, not along a band: nodes off both edges, and fewer than the
  // square of the debonded edge length (the front bends between the axes).
  int along_x = 0;
  while (along_x < 8 && end.beta[at.at({along_x + 1, 0})] < 0.5) ++along_x;
  CHECK(end.beta[at.at({0, 0})] < 0.5);
  CHECK(debonded_off_axes > 0);
  CHECK(debonded < (along_x + 1) * (along_x + 1));
  CHECK(std::abs(r.energy.relative_error()) <= 1e-3);
}

TEST_CASE("the frame of a plane in 3D: orthonormal, right-handed, t1 horizontal", "[solid]") {
  for (const Eigen::Vector3d& v : {Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0, 0, -1),
                                   Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(-0.3, 0.1, 0.9), Eigen::Vector3d(1, -1, 0)}) {
    const Eigen::Vector3d n = v.normalized();
    const Frame f = plane_frame(n);
    CHECK(std::abs(f.t1.norm() - 1) <= 1e-15);
    CHECK(std::abs(f.t2.norm() - 1) <= 1e-15);
    CHECK(std::abs(f.t1.dot(n)) <= 1e-15);
    CHECK(std::abs(f.t1.z()) <= 1e-15);  // horizontal: along the plane's trace on z = const
    CHECK((f.t1.cross(f.t2) - n).norm() <= 1e-15);
  }
  // The 2D frame is unchanged: t = (n_y, -n_x), exactly.
  const Frame f = plane_frame(Eigen::Vector3d(0.6, 0.8, 0));
  CHECK(f.t1 == Eigen::Vector3d(0.8, -0.6, 0));
}

namespace {

// 3D Hertz contact (Johnson, Contact Mechanics, s4.2): a rigid sphere of radius R pressed with
// a force P into an elastic half-space (E* = E / (1 - nu^2)):
//   a^3 = 3 P R / (4 E*),  p(r) = p0 sqrt(1 - r^2 / a^2),  p0 = 3 P / (2 pi a^2).
// The model: a quarter of a 4 mm cube (u_x = 0 on x = 0, u_z = 0 on z = 0), its bottom pushed
// up 0.1 mm against the sphere centred above its corner (0, 4, 0); frictionless and unbonded.
// P is the contact forces' vertical resultant (times 4), a and p0 follow from it.
struct Hertz3D {
  double h = 0, a = 0, p0 = 0;  // cell length; Hertz's radius and peak pressure for the FE's P
  double last = 0, peak = 0;    // the last pair in contact (its distance from the axis), the pressure on the axis
  double l2 = 0;                // relative L2 (tributary) error of Rbar_n / a against p(r)
  double penetration = 0, complementarity = 0, friction = 0;
};

Hertz3D hertz_sphere(int n) {
  const double R = 10, E = 1000, nu = 0.3, L = 4;
  std::ostringstream text;
  text << std::fixed << std::setprecision(3) << "mesh = { size = [4.0, 4.0, 4.0]; nx = " << n << "; ny = " << n << "; nz = " << n << "; element = \"H8\"; };\n"
       << "material = { E = " << E << "; nu = " << nu << "; };\n"
       << "interface = { boundary = \"top\"; circle = { centre = [0.0, " << L + R << ", 0.0]; radius = " << R
       << "; side = \"outside\"; }; Cn = 1000.0; Ct = 1000.0; w = 0.0; mu = 0.0; beta0 = 0.0; };\n"
       << "loads = ( { node_set = \"bottom\"; type = \"displacement\"; component = \"y\"; value = 0.1; },\n"
       << "          { node_set = \"left\"; type = \"displacement\"; component = \"x\"; value = 0.0; },\n"
       << "          { node_set = \"back\"; type = \"displacement\"; component = \"z\"; value = 0.0; } );\n"
       << "time = { T = 1.0; steps = 1; };\nintegrator = { method = \"contact-only\"; };\n";
  const Config cfg = test::config_from_text(text.str());
  const Model model = test::make_model(cfg);
  const Snapshot s = Simulation(cfg).run().snapshots.back();
  const Interface& I = model.interface();
  Hertz3D out;
  out.h = L / n;
  double P = 0, Rn_max = 0, un_max = 0;
  for (int i = 0; i < I.size(); ++i) {
    P -= s.Rbar[3 * i + 2] * I.pairs[i].frame.n.y();  // the sphere pushes the body down
    Rn_max = std::max(Rn_max, s.Rbar[3 * i + 2]);
    un_max = std::max(un_max, std::abs(s.u[3 * i + 2]));
  }
  P *= 4;
  const double Es = E / (1 - nu * nu);
  out.a = std::cbrt(3 * P * R / (4 * Es));
  out.p0 = 3 * P / (2 * M_PI * out.a * out.a);
  double num = 0, den = 0;
  for (int i = 0; i < I.size(); ++i) {
    const ContactPair& c = I.pairs[i];
    const Eigen::Vector3d& x = model.mesh().nodes[c.node];
    const double r = std::hypot(x.x(), x.z()), Rn = s.Rbar[3 * i + 2], g = c.g0 + s.u[3 * i + 2];
    const double p = Rn / c.measure, exact = out.p0 * std::sqrt(std::max(0.0, 1 - r * r / (out.a * out.a)));
    num += c.measure * (p - exact) * (p - exact);
    den += c.measure * exact * exact;
    if (Rn > 1e-9 * Rn_max) out.last = std::max(out.last, r);
    if (r == 0) out.peak = p;
    out.penetration = std::max(out.penetration, std::max(0.0, -g) / un_max);
    out.complementarity = std::max(out.complementarity, std::abs(g * Rn) / (Rn_max * un_max));
    out.friction = std::max(out.friction, std::hypot(s.Rbar[3 * i], s.Rbar[3 * i + 1]));
  }
  out.l2 = std::sqrt(num / den);
  return out;
}

}  // namespace

TEST_CASE("3D Hertz: a rigid sphere pressed into an elastic block, the gap from the geometry: contact radius "
          "and peak pressure against Hertz",
          "[solid]") {
  std::vector<double> l2;
  for (int n : {8, 12}) {
    const Hertz3D r = hertz_sphere(n);
    l2.push_back(r.l2);
    INFO("n = " << n << ": a " << r.a << ", last " << r.last << ", peak " << r.peak << " vs p0 " << r.p0 << ", L2 " << r.l2);
    CHECK(r.a > 2 * r.h);                                  // resolved: a few cells across
    CHECK(std::abs(r.last - r.a) <= r.h);                  // the contact ends within a cell of a
    CHECK(std::abs(r.peak / r.p0 - 1) <= 0.02);            // measured 0.7 % (the block is no half-space)
    CHECK(r.l2 <= 0.25);                                   // the profile, nodal pressures against p(r)
    CHECK(r.friction == 0.0);                              // frictionless, unbonded
    CHECK(r.penetration < 1e-9);                           // Signorini
    CHECK(r.complementarity < 1e-9);
  }
  CHECK(l2[1] < 0.6 * l2[0]);  // the profile converges: measured 0.143 -> 0.057 for h 0.5 -> 0.33
}

TEST_CASE("a rigid sphere anywhere: each contact pair's gap is its distance to the sphere, its normal radial", "[solid]") {
  // The sphere above an interior point of the top face, off every plane of symmetry.
  const Config cfg = test::config_from_text(R"(
mesh = { size = [4.0, 2.0, 3.0]; nx = 4; ny = 2; nz = 3; element = "H8"; };
material = { E = 1000.0; nu = 0.3; };
interface = { boundary = "top"; circle = { centre = [1.3, 7.5, 2.2]; radius = 5.0; side = "outside"; }; Cn = 1000.0; Ct = 1000.0; w = 0.0; mu = 0.3; beta0 = 0.0; };
loads = ( { node_set = "bottom"; type = "displacement"; component = "y"; value = 0.1; } );
time = { T = 1.0; steps = 1; };
integrator = { method = "contact-only"; };
)");
  const Model model = test::make_model(cfg);
  const Eigen::Vector3d c(1.3, 7.5, 2.2);
  REQUIRE(model.contact_nodes() == 5 * 4);
  for (const ContactPair& p : model.interface().pairs) {
    const Eigen::Vector3d x = model.mesh().nodes[p.node];
    CHECK(p.g0 == Approx((x - c).norm() - 5.0).margin(1e-12));
    CHECK((p.frame.n - (x - c).normalized()).norm() <= 1e-12);
    CHECK((p.frame.t1.cross(p.frame.t2) - p.frame.n).norm() <= 1e-12);
  }
}

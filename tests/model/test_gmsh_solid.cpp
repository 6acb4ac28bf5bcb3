// 3D gmsh meshes (fem/gmsh_mesh with Physical Volumes): tetrahedra pass the patch test and
// their boundary triangles carry the faces' areas; mirrored cells are turned; a block of
// tetrahedra pressed onto a frictionless base carries the uniform uniaxial stress exactly; a
// plate of gmsh hexahedra peels like the built-in box.
#include "helpers.hpp"
#include "solid_checks.hpp"
#include "rccm/app/simulation.hpp"
#include "rccm/contact/solver_tuning.hpp"
#include "rccm/fem/box_mesh.hpp"
#include "rccm/fem/gmsh_mesh.hpp"

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <iomanip>
#include <map>

using namespace rccm;

namespace {

const std::string fixtures = std::string(RCCM_SOURCE_DIR) + "/tests/meshes/";

Mesh read(const std::string& file, std::map<std::string, double> parameters = {}) {
  MeshParams p;
  p.file = fixtures + file;
  p.parameters = std::move(parameters);
  return read_gmsh(p, "test.cfg:1: mesh.file");
}

double volume(const Mesh& m, const std::vector<int>& c) {
  const auto& x = m.nodes;
  if (c.size() == 4) return (x[c[1]] - x[c[0]]).cross(x[c[2]] - x[c[0]]).dot(x[c[3]] - x[c[0]]) / 6;
  double v = 0;  // a hexahedron as 6 tetrahedra around its diagonal 0-6
  for (const auto& [a, b] : {std::pair{1, 2}, {2, 3}, {3, 7}, {7, 4}, {4, 5}, {5, 1}})
    v += (x[c[a]] - x[c[0]]).cross(x[c[b]] - x[c[0]]).dot(x[c[6]] - x[c[0]]) / 6;
  return v;
}

/// A node's place, to 1e-6 mm: the same node in two meshes, whatever their numbering.
std::array<long, 3> position_key(const Eigen::Vector3d& x) {
  return {std::lround(1e6 * x.x()), std::lround(1e6 * x.y()), std::lround(1e6 * x.z())};
}

/// Where a node of a placed mesh was in the reference one.
using Unplace = std::function<Eigen::Vector3d(const Eigen::Vector3d&)>;

/// The contact pairs of `m` by their nodes' places, each place seen in the reference mesh.
std::map<std::array<long, 3>, int> pairs_by_position(const Model& m, const Unplace& unplace = [](const Eigen::Vector3d& x) { return x; }) {
  std::map<std::array<long, 3>, int> at;
  for (int i = 0; i < m.interface().size(); ++i) at[position_key(unplace(m.mesh().nodes[m.interface().pairs[i].node]))] = i;
  return at;
}

/// Euler-50 and sweeps to 1e-12 for the corner peel compared across meshes: the pairs come in
/// another order there (another sweep order), the results agree to the tolerance.
const std::vector<std::string> fixed_steps = {"integrator={method=\"euler\";}", "time.steps=50", "solver.tolerance=1e-12"};

/// A body of an MSH 2.2 file made from a built-in box: shifted, its node sets named as
/// Physical Surfaces (their boundary quads) and Physical Points (one node).
struct MshPart {
  Mesh box;
  Eigen::Vector3d shift = Eigen::Vector3d::Zero();
  std::string volume;
  std::vector<std::pair<std::string, std::string>> surfaces, points;  // group name, the box's node set
  std::vector<std::pair<std::string, std::string>> curves = {};       // written as lines between the set's nodes in turn
};

Mesh plate_box(int n) { return make_box(test::box(n, 1.0, n, n, 1, n)); }

/// Writes the parts, turned by Q about the origin after their shifts, as an MSH 2.2 file
/// (each part its own nodes) in the build tree.
std::string write_msh(const std::string& name, const std::vector<MshPart>& parts, const Eigen::Matrix3d& Q) {
  std::ostringstream names, nodes, elements;
  int group = 0, node_base = 0, node_count = 0, element = 0;
  for (const MshPart& part : parts) node_count += part.box.num_nodes();
  nodes << std::setprecision(17);
  for (const MshPart& part : parts) {
    const Mesh& m = part.box;
    for (int k = 0; k < m.num_nodes(); ++k) {
      const Eigen::Vector3d x = Q * (m.nodes[k] + part.shift);
      nodes << node_base + k + 1 << " " << x.x() << " " << x.y() << " " << x.z() << "\n";
    }
    const auto write = [&](int type, const std::vector<int>& cell) {
      elements << ++element << " " << type << " 2 " << group << " " << group;
      for (int k : cell) elements << " " << node_base + k + 1;
      elements << "\n";
    };
    names << "3 " << ++group << " \"" << part.volume << "\"\n";
    for (const auto& c : m.cells) write(5, c);
    for (const auto& [surface, set] : part.surfaces) {
      names << "2 " << ++group << " \"" << surface << "\"\n";
      for (const auto& f : m.facets_of(set)) write(3, f);
    }
    for (const auto& [curve, set] : part.curves) {
      names << "1 " << ++group << " \"" << curve << "\"\n";
      const std::vector<int>& nodes_of = m.node_set(set);
      for (std::size_t k = 0; k + 1 < nodes_of.size(); ++k) write(1, {nodes_of[k], nodes_of[k + 1]});
    }
    for (const auto& [point, set] : part.points) {
      names << "0 " << ++group << " \"" << point << "\"\n";
      write(15, {m.node_set(set).front()});
    }
    node_base += m.num_nodes();
  }
  return test::write_temp_file(name, "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n" + std::to_string(group) + "\n" +
                                         names.str() + "$EndPhysicalNames\n$Nodes\n" + std::to_string(node_count) + "\n" +
                                         nodes.str() + "$EndNodes\n$Elements\n" + std::to_string(element) + "\n" +
                                         elements.str() + "$EndElements\n");
}

/// A 2D mesh of Q4 cells extruded along z into one layer of H8 cells of `depth`: each node
/// set holds its nodes of both faces; the facets are the side quads of the boundary edges.
Mesh extrude(const Mesh& plane, double depth) {
  Mesh m;
  m.dim = 3;
  const int n = plane.num_nodes();
  for (double z : {0.0, depth})
    for (const Eigen::Vector3d& x : plane.nodes) m.nodes.emplace_back(x.x(), x.y(), z);
  for (const auto& c : plane.cells) {
    REQUIRE(c.size() == 4);
    m.cells.push_back({c[0], c[1], c[2], c[3], c[0] + n, c[1] + n, c[2] + n, c[3] + n});
  }
  m.cell_body = plane.cell_body;
  m.body_names = plane.body_names;
  for (const auto& e : plane.facets) m.facets.push_back({e[0], e[1], e[1] + n, e[0] + n});
  for (const auto& [name, set] : plane.node_sets) {
    std::vector<int>& both = m.node_sets[name];
    for (int k : set) both.push_back(k), both.push_back(k + n);
  }
  return m;
}

/// The corner peel's plate (n x 1 x n H8) turned by Q about the origin: its body "plate",
/// its face "bottom", its corner "top_left_back".
std::string turned_plate(int n, const Eigen::Matrix3d& Q, const std::string& name = "turned_plate.msh") {
  return write_msh(name, {{plate_box(n), Eigen::Vector3d::Zero(), "plate", {{"bottom", "bottom"}}, {{"top_left_back", "top_left_back"}}}}, Q);
}

/// The corner peel `a_cfg` and its placed twin `b_cfg` (the base's normal `n`, the loads turned
/// alike) give the same beta, R_n, u_n, |R_t| and |u_t| pair by pair, within 1e-8.
void require_turned_alike(const Config& a_cfg, const Config& b_cfg, const Unplace& unplace, const Eigen::Vector3d& n) {
  const RunResult a = Simulation(a_cfg).run(), b = Simulation(b_cfg).run();
  const Model ma = test::make_model(a_cfg), mb = test::make_model(b_cfg);
  REQUIRE(ma.contact_nodes() == mb.contact_nodes());
  const auto pair_at = pairs_by_position(mb, unplace);  // the placed mesh's pairs by their place before
  const Snapshot &sa = a.snapshots.back(), &sb = b.snapshots.back();
  REQUIRE(sa.beta.minCoeff() < 0.5);
  REQUIRE(sa.beta.maxCoeff() > 0.5);
  const double R = sa.Rbar.cwiseAbs().maxCoeff(), u = sa.u.cwiseAbs().maxCoeff();
  for (int i = 0; i < ma.interface().size(); ++i) {
    const int j = pair_at.at(position_key(ma.mesh().nodes[ma.interface().pairs[i].node]));
    CHECK((mb.interface().pairs[j].frame.n - n).norm() <= 1e-14);
    CHECK(std::abs(sa.beta[i] - sb.beta[j]) <= 1e-8);
    CHECK(std::abs(sa.Rbar[3 * i + 2] - sb.Rbar[3 * j + 2]) <= 1e-8 * R);
    CHECK(std::abs(std::hypot(sa.Rbar[3 * i], sa.Rbar[3 * i + 1]) - std::hypot(sb.Rbar[3 * j], sb.Rbar[3 * j + 1])) <= 1e-8 * R);
    CHECK(std::abs(sa.u[3 * i + 2] - sb.u[3 * j + 2]) <= 1e-8 * u);
    CHECK(std::abs(std::hypot(sa.u[3 * i], sa.u[3 * i + 1]) - std::hypot(sb.u[3 * j], sb.u[3 * j + 1])) <= 1e-8 * u);
  }
}

}  // namespace

TEST_CASE("gmsh 3D: a block of tetrahedra passes the patch test, its faces' triangles carry their areas", "[gmsh][solid]") {
  const Mesh m = read("block_tets.geo");
  REQUIRE(m.dim == 3);
  REQUIRE(m.body_names == std::vector<std::string>{"block"});
  double total = 0;
  for (const auto& c : m.cells) {
    REQUIRE(c.size() == 4);
    CHECK(volume(m, c) > 0);
    total += volume(m, c);
  }
  CHECK(total == Approx(3.0 * 2.0 * 1.5).epsilon(1e-12));
  CHECK(test::check_rigid_motions_and_patch(m, 1000.0, 0.3) > 0);
  // Every boundary facet a triangle; each face's tributary areas sum to its area, the
  // normals point out.
  for (const auto& f : m.facets) CHECK(f.size() == 3);
  const std::map<std::string, std::pair<Eigen::Vector3d, double>> faces = {{"bottom", {-Eigen::Vector3d::UnitY(), 4.5}},
                                                                          {"top", {Eigen::Vector3d::UnitY(), 4.5}},
                                                                          {"left", {-Eigen::Vector3d::UnitX(), 3.0}},
                                                                          {"back", {-Eigen::Vector3d::UnitZ(), 6.0}}};
  for (const auto& [name, normal_area] : faces) {
    INFO(name);
    const std::vector<int>& set = m.node_set(name);
    double area = 0;
    for (double a : m.tributary_measures(set, m.facets_of(name))) area += a;
    CHECK(area == Approx(normal_area.second).epsilon(1e-12));
    for (const Eigen::Vector3d& n : m.outward_normals(set, m.facets_of(name))) CHECK((n - normal_area.first).norm() <= 1e-12);
  }
  for (const int n : m.node_set("top_left")) CHECK((m.nodes[n].x() == 0 && m.nodes[n].y() == 2));
}

TEST_CASE("gmsh 3D: mirrored hexahedra and tetrahedra are turned to a positive volume, their faces outward", "[gmsh][solid]") {
  const Mesh m = read("mirrored.msh");
  REQUIRE(m.body_names == std::vector<std::string>{"cube", "tet"});
  REQUIRE(m.cells.size() == 2);
  CHECK(volume(m, m.cells[0]) == Approx(1.0).epsilon(1e-14));
  CHECK(volume(m, m.cells[1]) == Approx(1.0 / 6).epsilon(1e-14));
  CHECK(m.facets.size() == 6 + 4);
  for (int body = 0; body < 2; ++body) {
    const std::vector<int>& set = m.node_set(m.body_names[body]);
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (int n : set) centre += m.nodes[n] / double(set.size());
    for (const BoundaryFace& f : m.boundary_faces(m.facets_of(m.body_names[body]))) {
      Eigen::Vector3d mid = Eigen::Vector3d::Zero();
      for (int n : f.nodes) mid += m.nodes[n] / double(f.nodes.size());
      CHECK(f.outward.dot(mid - centre) > 0);
    }
  }
  CHECK(test::check_rigid_motions_and_patch(m, 1000.0, 0.3) == 0);
}

namespace {

/// A block of Lx x 2 x Lz mm (E = 1000 MPa, nu = 0.3) on a frictionless, unbonded base,
/// loaded from its top by `loads` so that it carries the uniaxial stress sigma_yy = -sigma:
/// every contact node's pressure is sigma, its slip the Poisson expansion nu sigma / E |(x, z)|
/// about the corner held in x and z, the resultant sigma Lx Lz.
void check_uniform_compression(const std::string& mesh, const std::string& loads, double sigma, double Lx, double Lz) {
  const double E = 1000, nu = 0.3;
  const Config cfg = test::config_from_text(mesh + R"(
material = { E = 1000.0; nu = 0.3; };
interface = { boundary = "bottom"; normal = [0.0, 1.0, 0.0]; Cn = 1000.0; Ct = 1000.0; w = 0.0; mu = 0.0; beta0 = 0.0; };
time = { T = 1.0; steps = 1; };
integrator = { method = "contact-only"; };
solver = { active_set = true; };   # the exact step: the slip exact to round-off
loads = ( )" + loads + " );\n");
  const Model model = test::make_model(cfg);
  const Snapshot s = Simulation(cfg).run().snapshots.back();
  const Interface& I = model.interface();
  REQUIRE(I.layout.dim == 3);
  double force = 0;
  for (int i = 0; i < I.size(); ++i) {
    const Eigen::Vector3d x = model.mesh().nodes[I.pairs[i].node];
    INFO("node at " << x.transpose());
    CHECK(s.Rbar[3 * i + 2] / I.pairs[i].measure == Approx(sigma).epsilon(1e-9));
    CHECK(std::hypot(s.Rbar[3 * i], s.Rbar[3 * i + 1]) <= 1e-12 * sigma);
    // Zero to the cancellation in u = W0 y + q0, whose terms grow like 1 / springs_floor once
    // K0 holds the debonded pairs by their floor springs alone (docs/MODEL.md s4).
    CHECK(std::abs(s.u[3 * i + 2]) <= 1e-13 / tuning::springs_floor);
    CHECK(std::hypot(s.u[3 * i], s.u[3 * i + 1]) == Approx(nu * sigma / E * std::hypot(x.x(), x.z())).margin(1e-12));
    force += s.Rbar[3 * i + 2];
  }
  CHECK(force == Approx(sigma * Lx * Lz).epsilon(1e-10));
}

const std::string tets = "mesh = { file = \"" + fixtures + "block_tets.geo\"; };\n";
// The two top edges through the corner (0, 2, 0) hold the exact solution's u_x = 0, u_z = 0.
const std::string held = R"(,
  { node_set = "top_left"; type = "displacement"; component = "x"; value = 0.0; },
  { node_set = "top_back"; type = "displacement"; component = "z"; value = 0.0; })";

}  // namespace

TEST_CASE("gmsh 3D: a block of tetrahedra pressed onto a frictionless base carries the uniform uniaxial stress", "[gmsh][solid]") {
  // The top pushed down by d = 0.01 mm: sigma = E d / H.
  check_uniform_compression(tets, R"({ node_set = "top"; type = "displacement"; component = "y"; value = -0.01; })" + held,
                            1000 * 0.01 / 2, 3.0, 1.5);
}

TEST_CASE("3D pressures and tractions: a pressure or a downward traction on the top face of tetrahedra or "
          "hexahedra is carried as the uniform uniaxial stress",
          "[gmsh][solid]") {
  const double p = 7.5;  // MPa
  for (const char* load : {R"({ node_set = "top"; type = "pressure"; value = 7.5; })",
                           R"({ node_set = "top"; type = "traction"; component = "y"; value = -7.5; })"}) {
    INFO(load);
    check_uniform_compression(tets, load + held, p, 3.0, 1.5);
    // The box of H8: its faces x = 0 and z = 0 hold u_x = 0 and u_z = 0.
    check_uniform_compression(R"(mesh = { size = [3.0, 2.0, 1.5]; nx = 3; ny = 2; nz = 2; element = "H8"; };)", std::string(load) + R"(,
  { node_set = "left"; type = "displacement"; component = "x"; value = 0.0; },
  { node_set = "back"; type = "displacement"; component = "z"; value = 0.0; })",
                              p, 3.0, 1.5);
  }
}

TEST_CASE("gmsh 3D: a plate of gmsh hexahedra peels by one corner like the built-in box", "[gmsh][solid]") {
  const Config box = test::corner_peel(4, fixed_steps);
  const Config gmsh = test::corner_peel(4, fixed_steps, "mesh = { file = \"" + fixtures + "plate_hex.geo\"; parameters = { n = 4.0; }; };");
  const RunResult a = Simulation(box).run(), b = Simulation(gmsh).run();
  const Model ma = test::make_model(box), mb = test::make_model(gmsh);
  REQUIRE(mb.mesh().body_names == std::vector<std::string>{"plate"});
  REQUIRE(ma.contact_nodes() == mb.contact_nodes());
  REQUIRE(a.snapshots.size() == b.snapshots.size());
  const auto pair_at = pairs_by_position(mb);
  const Snapshot &sa = a.snapshots.back(), &sb = b.snapshots.back();
  CHECK(sa.beta.minCoeff() < 0.5);  // the peel has begun
  for (int i = 0; i < ma.interface().size(); ++i) {
    const int j = pair_at.at(position_key(ma.mesh().nodes[ma.interface().pairs[i].node]));
    CHECK(std::abs(sa.beta[i] - sb.beta[j]) <= 1e-8);
    CHECK(std::abs(sa.Rbar[3 * i + 2] - sb.Rbar[3 * j + 2]) <= 1e-8 * sa.Rbar.cwiseAbs().maxCoeff());
  }
}

TEST_CASE("3D node-set boxes: a z range selects within it, four numbers every z, and a box on a gmsh volume loads "
          "the plate like its Physical Point",
          "[gmsh][solid]") {
  // The built-in box, 5 x 2 x 5 nodes at integer coordinates.
  const Config box = test::corner_peel(4, {R"(mesh.node_sets=(
      { name = "back_top_edge"; box = [0.0, 4.0, 1.0, 1.0, 0.0, 0.0]; },
      { name = "left_top_edge"; box = [0.0, 0.0, 1.0, 1.0]; },
      { name = "left_top_part"; box = [0.0, 0.0, 1.0, 1.0, 2.0, 4.0]; } ))"});
  const Mesh m = make_mesh(box);
  const auto coordinates_of = [&](const std::string& set, int axis) {
    std::vector<double> c;
    for (int n : m.node_set(set)) c.push_back(m.nodes[n][axis]);
    std::sort(c.begin(), c.end());
    return c;
  };
  CHECK(coordinates_of("back_top_edge", 0) == std::vector<double>{0, 1, 2, 3, 4});
  CHECK(coordinates_of("back_top_edge", 2) == std::vector<double>(5, 0.0));
  CHECK(coordinates_of("left_top_edge", 2) == std::vector<double>{0, 1, 2, 3, 4});
  CHECK(coordinates_of("left_top_part", 2) == std::vector<double>{2, 3, 4});
  for (const std::string set : {"back_top_edge", "left_top_edge", "left_top_part"})
    for (int n : m.node_set(set)) CHECK(m.nodes[n][1] == 1.0);

  // The gmsh plate lifted at the corner given by a box instead of its Physical Point.
  const std::string plate = "file = \"" + fixtures + "plate_hex.geo\"; parameters = { n = 4.0; };";
  const Config named = test::corner_peel(4, fixed_steps, "mesh = { " + plate + " };");
  std::vector<std::string> by_box = fixed_steps;
  by_box.push_back(R"(loads=({ node_set = "corner"; type = "displacement"; component = "y"; value = 0.15; }))");
  const Config boxed = test::corner_peel(
      4, by_box, "mesh = { " + plate + " node_sets = ( { name = \"corner\"; box = [0.0, 0.0, 1.0, 1.0, 0.0, 0.0]; } ); };");
  const Mesh mb = make_mesh(boxed);
  REQUIRE(mb.node_set("corner") == mb.node_set("top_left_back"));
  const RunResult a = Simulation(named).run(), b = Simulation(boxed).run();
  CHECK(a.snapshots.back().beta.minCoeff() < 0.5);  // the peel has begun
  CHECK((a.snapshots.back().beta - b.snapshots.back().beta).cwiseAbs().maxCoeff() == 0.0);
}

TEST_CASE("gmsh 3D: a bad volume mesh is refused, naming the file and the physical group", "[gmsh][solid]") {
  const auto refused = [](const std::string& file, const std::string& expect) {
    MeshParams p;
    p.file = file;
    INFO(file);
    CHECK_THROWS_WITH(read_gmsh(p, "test.cfg:1: mesh.file"), Catch::Contains("test.cfg:1: mesh.file: " + file) && Catch::Contains(expect));
  };
  const std::string box = "SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 1, 1, 1};\nBox(2) = {2, 0, 0, 1, 1, 1};\nMesh.MeshSizeMax = 0.5;\n";
  refused(test::write_temp_file("solid_quadratic.geo", box + "Physical Volume(\"cube\") = {1, 2};\nMesh.ElementOrder = 2;\nMesh 3;\n"),
          "Physical Volume 'cube' has Tetrahedron 10 cells: rccm reads linear tetrahedra (T4) and hexahedra (H8); mesh with "
          "Mesh.ElementOrder = 1");
  refused(test::write_temp_file("solid_left_out.geo", box + "Physical Volume(\"cube\") = {1};\n"), "volume 2 is meshed but in no Physical Volume");
  refused(test::write_temp_file("solid_clash.geo", box + "Physical Volume(\"cube\") = {1, 2};\nPhysical Surface(\"cube\") = {1};\n"),
          "Physical Surface 'cube' has the name of another physical group");
}

namespace {

/// An orthotropic ply (3D) with axis 3 along `axis3` and axis 1 at `angle` degrees from its
/// reference axis (README "3D"), as a config override.
std::string ply(const Eigen::Vector3d& axis3, double angle) {
  std::ostringstream m;
  m << std::setprecision(17) << "material={E1=1.4e5; E2=1.0e4; E3=1.0e4; nu12=0.3; nu13=0.3; nu23=0.45; G12=5.0e3; "
    << "G13=5.0e3; G23=3.4e3; angle=" << angle << "; axis3=[" << axis3.x() << ", " << axis3.y() << ", " << axis3.z() << "];}";
  return m.str();
}

/// The corner peel pulled up by a force at its corner (components add up; prescribed
/// components would hold the others at 0), as given for the reference plate (`reference`) and
/// for the plate turned by Q (`turned`: the base's normal Q y, the force turned alike).
struct CornerPull {
  static constexpr double F = 200;  // N: the plate's corner region debonds, the rest holds
  explicit CornerPull(const Eigen::Matrix3d& Q) : n(Q.col(1)) {
    const Eigen::Vector3d lift = F * n;
    std::ostringstream normal, loads;
    normal << std::setprecision(17) << "interface.normal=[" << n.x() << ", " << n.y() << ", " << n.z() << "]";
    loads << std::setprecision(17) << "loads=(";
    for (int k = 0; k < 3; ++k)
      loads << (k ? ", " : "") << "{node_set=\"top_left_back\"; type=\"force\"; component=\"" << "xyz"[k] << "\"; value=" << lift[k] << ";}";
    loads << ")";
    reference.push_back("loads=({node_set=\"top_left_back\"; type=\"force\"; component=\"y\"; value=" + std::to_string(F) + ";})");
    turned.insert(turned.end(), {normal.str(), loads.str()});
  }
  Eigen::Vector3d n;  // the turned base's normal
  std::vector<std::string> reference = fixed_steps, turned = fixed_steps;
};

const Eigen::Matrix3d oblique = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();

}  // namespace

TEST_CASE("3D rotation invariance: the corner peel turned about an oblique axis gives the same beta, "
          "normal reactions and slip magnitudes, isotropic or an orthotropic ply turned alike",
          "[gmsh][solid]") {
  const Eigen::Matrix3d& Q = oblique;
  CornerPull pull(Q);
  const Eigen::Vector3d& n = pull.n;
  if (GENERATE(false, true)) {
    // The ply in the plate's plane: axis 3 along y, axis 1 at 30 degrees from x, (c, 0, -s).
    // Turned: axis 3 along Q y, axis 1 along Q (c, 0, -s), at the angle from the reference
    // axis of Q y (x projected on its plane; axis 2 = axis 3 x axis 1).
    const double a = 30 * M_PI / 180;
    const Eigen::Vector3d axis1 = Q * Eigen::Vector3d(std::cos(a), 0, -std::sin(a));
    const Eigen::Vector3d r1 = (Eigen::Vector3d::UnitX() - n.x() * n).normalized(), r2 = n.cross(r1);
    pull.reference.push_back(ply(Eigen::Vector3d::UnitY(), 30));
    REQUIRE(std::abs(n.x()) < 0.9);  // x is the reference of Q y
    pull.turned.push_back(ply(n, std::atan2(axis1.dot(r2), axis1.dot(r1)) * 180 / M_PI));
  }
  const Config a_cfg = test::corner_peel(4, pull.reference);
  const Config b_cfg = test::corner_peel(4, pull.turned, "mesh = { file = \"" + turned_plate(4, Q) + "\"; };");
  require_turned_alike(a_cfg, b_cfg, [&](const Eigen::Vector3d& x) { return Eigen::Vector3d(Q.transpose() * x); }, n);
}

TEST_CASE("3D placement: mesh.origin and mesh.rotation move the built-in box and a gmsh plate as a turned file does",
          "[gmsh][solid]") {
  // The box's origin is its lower corner and the centre of the turn; a file's origin is the
  // centre only. The node set of the load is found in the unturned frame.
  const Eigen::Matrix3d& Q = oblique;
  const Eigen::Vector3d o(2.0, -1.0, 3.0);
  const CornerPull pull(Q);
  const bool box = GENERATE(true, false);
  INFO((box ? "the built-in box" : "a gmsh file"));
  std::ostringstream placement;
  placement << std::setprecision(17) << "origin = [" << o.x() << ", " << o.y() << ", " << o.z()
            << "]; rotation = { axis = [1.0, 2.0, 3.0]; angle = " << 0.7 * 180 / M_PI << "; };";
  const std::string source = box ? "size = [4.0, 1.0, 4.0]; nx = 4; ny = 1; nz = 4; element = \"H8\";"
                                 : "file = \"" + turned_plate(4, Eigen::Matrix3d::Identity(), "placed_plate.msh") + "\";";  // its own file: tests run side by side
  const Config a_cfg = test::corner_peel(4, pull.reference, "mesh = { " + source + " };");
  const Config b_cfg = test::corner_peel(4, pull.turned, "mesh = { " + source + " " + placement.str() + " };");
  const Model mb = test::make_model(b_cfg);
  CHECK((mb.mesh().placement.rotation - Q).norm() <= 1e-14);
  require_turned_alike(a_cfg, b_cfg, [&](const Eigen::Vector3d& x) {
    const Eigen::Vector3d back = Q.transpose() * (x - o);
    return Eigen::Vector3d(box ? back : Eigen::Vector3d(back + o));
  }, pull.n);
}

TEST_CASE("3D body-body interface: a plate peeled from a held elastic block behaves as on a rigid base", "[gmsh][solid]") {
  // The block below the plate (its own nodes at y = 0) held at every node, in place or moved
  // by d (the lifted corner moved alike): u = u_plate - u_block is the rigid base's u, the
  // pairs' frames from the two faces' normals, the areas from the plate's face.
  const Eigen::Vector3d d = GENERATE(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.01, -0.02, 0.03));
  INFO("block moved by " << d.transpose());
  const std::string file = write_msh("plate_on_block.msh",
                                     {{plate_box(4), Eigen::Vector3d::Zero(), "plate", {{"bottom", "bottom"}}, {{"top_left_back", "top_left_back"}}},
                                      {plate_box(4), Eigen::Vector3d(0, -1, 0), "block", {{"block_top", "top"}}, {}}},
                                     Eigen::Matrix3d::Identity());
  const Config rigid = test::corner_peel(4, fixed_steps);
  std::ostringstream loads;
  loads << std::setprecision(17) << "loads = ( { node_set = \"top_left_back\"; type = \"displacement\"; component = \"y\"; value = "
        << 0.15 + d.y() << "; }";
  for (int k = 0; k < 3; ++k)
    loads << ",\n  { node_set = \"block\"; type = \"displacement\"; component = \"" << "xyz"[k] << "\"; value = " << d[k] << "; }";
  loads << " );\n";
  const Config two = test::config_from_text("mesh = { file = \"" + file + R"("; };
material = { E = 6.9e4; nu = 0.333; };
interface = { boundary = "bottom"; opposite = "block_top"; Cn = 2.0e5; Ct = 2.0e5; w = 1.0e-6; alpha = 1.0; mu = 0.2; beta0 = 1.0; };
)" + loads.str() + R"(
time = { T = 5.0; steps = 50; };
integrator = { method = "euler"; };
solver = { active_set = false; tolerance = 1e-12; };
)");
  const RunResult a = Simulation(rigid).run(), b = Simulation(two).run();
  const Model ma = test::make_model(rigid), mb = test::make_model(two);
  REQUIRE(mb.contact_nodes() == ma.contact_nodes());
  for (const ContactPair& c : mb.interface().pairs) {
    CHECK(c.opposite >= 0);
    CHECK((mb.mesh().nodes[c.node] - mb.mesh().nodes[c.opposite]).norm() <= 1e-12);
    CHECK((c.frame.n - Eigen::Vector3d::UnitY()).norm() <= 1e-12);
    CHECK(c.g0 == 0.0);
  }
  const auto pair_at = pairs_by_position(mb);
  const Snapshot &sa = a.snapshots.back(), &sb = b.snapshots.back();
  REQUIRE(sa.beta.minCoeff() < 0.5);
  const double R = sa.Rbar.cwiseAbs().maxCoeff(), u = sa.u.cwiseAbs().maxCoeff();
  for (int i = 0; i < ma.interface().size(); ++i) {
    const int j = pair_at.at(position_key(ma.mesh().nodes[ma.interface().pairs[i].node]));
    CHECK(mb.interface().pairs[j].measure == Approx(ma.interface().pairs[i].measure).epsilon(1e-14));
    CHECK(std::abs(sa.beta[i] - sb.beta[j]) <= 1e-8);
    for (int k = 0; k < 3; ++k) {
      CHECK(std::abs(sa.Rbar[3 * i + k] - sb.Rbar[3 * j + k]) <= 1e-8 * R);
      CHECK(std::abs(sa.u[3 * i + k] - sb.u[3 * j + k]) <= 1e-8 * u);
    }
  }
}

TEST_CASE("3D cylinder: config/coating-curved.cfg extruded into a slab of H8 held at u_z = 0 reproduces "
          "the 2D coating on its circle",
          "[gmsh][solid]") {
  // 20 x 4 cells over the 120 degrees, Euler-100 over the first 2 s (the front starts), the
  // sweeps and the exact step to 1e-12; the cylinder's axis is z.
  const std::vector<std::string> settings = {"mesh.parameters.na=20", "integrator={method=\"euler\";}", "time.T=2.0",
                                             "time.steps=100", "output.times=[1.0, 2.0]", "solver.tolerance=1e-12",
                                             "output.watch=()", "output.probes=()"};
  const Config plane = load_config(test::shipped("coating-curved.cfg"), settings);
  const Mesh flat = read_gmsh(plane.mesh, "coating-curved.cfg");
  const std::string file = write_msh("coating_slab.msh", {{extrude(flat, 1.0), Eigen::Vector3d::Zero(), "coating",
                                                            {{"bonded", "bonded"}}, {}, {{"tip", "tip"}}}},
                                     Eigen::Matrix3d::Identity());
  const Config slab = test::config_from_text("mesh = { file = \"" + file + R"("; };
material = { E = 3000.0; nu = 0.35; };
interface = { boundary = "bonded"; circle = { centre = [0.0, 0.0, 0.0]; radius = 20.0; side = "outside"; axis = [0.0, 0.0, 2.0]; };
              Cn = 1.0e4; Ct = 1.0e4; w = 0.01; alpha = 0.5; mu = 0.3; };
loads = ( { node_set = "tip"; type = "displacement"; component = "y"; value = 1.0; },
          { node_set = "coating"; type = "displacement"; component = "z"; value = 0.0; } );
time = { T = 2.0; steps = 100; };
integrator = { method = "euler"; };
solver = { tolerance = 1e-12; active_set = true; };
output = { times = [1.0, 2.0]; };
)");
  const RunResult r2 = Simulation(plane).run(), r3 = Simulation(slab).run();
  const Model m2 = test::make_model(plane), m3 = test::make_model(slab);
  REQUIRE(m3.contact_nodes() == 2 * m2.contact_nodes());
  const auto pair_at = pairs_by_position(m2);  // the 2D pair at (x, y, 0)
  REQUIRE(r2.snapshots.size() == r3.snapshots.size());
  CHECK(r2.snapshots.back().beta.minCoeff() < 0.5);  // the front has started
  for (std::size_t s = 0; s < r2.snapshots.size(); ++s) {
    const Snapshot &a = r2.snapshots[s], &b = r3.snapshots[s];
    const double u_scale = a.u.cwiseAbs().maxCoeff(), R_scale = a.Rbar.cwiseAbs().maxCoeff();
    REQUIRE(R_scale > 0);
    for (int j = 0; j < m3.contact_nodes(); ++j) {
      const ContactPair& c = m3.interface().pairs[j];
      const Eigen::Vector3d x = m3.mesh().nodes[c.node];
      const int i = pair_at.at(position_key(Eigen::Vector3d(x.x(), x.y(), 0.0)));
      const ContactPair& c2 = m2.interface().pairs[i];
      CHECK((c.frame.n - c2.frame.n).norm() <= 1e-12);  // radial, off the axis
      CHECK(c.g0 == Approx(c2.g0).margin(1e-12));
      CHECK(std::abs(b.beta[j] - a.beta[i]) <= 1e-8);
      CHECK(std::abs(b.u[3 * j] - a.u[2 * i]) <= 1e-8 * u_scale);          // u_t1 = u_t
      CHECK(std::abs(b.u[3 * j + 1]) <= 1e-12 * u_scale);                  // along the axis
      CHECK(std::abs(b.u[3 * j + 2] - a.u[2 * i + 1]) <= 1e-8 * u_scale);  // u_n
      CHECK(std::abs(2 * b.Rbar[3 * j + 2] - a.Rbar[2 * i + 1]) <= 1e-8 * R_scale);
      CHECK(std::abs(2 * b.Rbar[3 * j] - a.Rbar[2 * i]) <= 1e-8 * R_scale);
    }
  }
}

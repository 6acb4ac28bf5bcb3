// Several bodies and interfaces between them (issue 16): a bonded interface transmits a
// uniform stress exactly (a patch test across it, with the spring's opening p / Cn); two
// blocks glued by a stiff interface are one block up to the penalty error, which shrinks as
// C grows; several interfaces keep the symmetry of a symmetric problem and are invariant
// under rotation; meshes that do not match, shared nodes and missing materials are refused.
#include "helpers.hpp"
#include "rccm/app/simulation.hpp"
#include "rccm/base/errors.hpp"
#include "rccm/model/body_state.hpp"

#include <catch2/catch.hpp>

#include <fstream>
#include <iomanip>
#include <iterator>
#include <sstream>

using namespace rccm;

namespace {

const std::string fixture = std::string(RCCM_SOURCE_DIR) + "/tests/meshes/two_blocks.geo";

/// The two blocks of tests/meshes/two_blocks.geo (10 x 2 each, y in [0, 4]) with `rest`.
Config two_blocks(const std::string& rest, const std::vector<std::string>& overrides = {}) {
  return test::config_from_text("mesh = { file = \"" + fixture + "\"; };\n" + rest, overrides);
}

/// The bulk displacement at T of a run (contact-only: beta stays at beta0).
Eigen::VectorXd displacement_at_T(const Config& cfg) {
  const Model model = test::make_model(cfg);
  Eigen::VectorXd u;
  RunOptions o;
  o.observer = [&](const AcceptedStep& a) { u = body_state(model, a.state).u; };
  Simulation(cfg, o).run();
  return u;
}

/// u of the node at x (mm) of a mesh.
Eigen::Vector2d at(const Model& m, const Eigen::VectorXd& u, double x, double y) {
  for (int n = 0; n < m.mesh().num_nodes(); ++n)
    if ((m.mesh().nodes[n] - Eigen::Vector3d(x, y, 0)).norm() < 1e-9) return u.segment<2>(m.mesh().dof(n, 0));
  FAIL("no node at (" << x << ", " << y << ")");
  return {};
}

const std::string glue = R"(
  boundary = "upper_bottom"; opposite = "lower_top"; Ct = 1e3; w = 1e9; alpha = 1.0; mu = 0.3;
)";

}  // namespace

TEST_CASE("patch test across a body-body interface: uniform stress, opening p / Cn, each body its material",
          "[bodies]") {
  // Rollers on the bottom and the left, a pull p on the top: sigma_yy = p in both blocks,
  // the glue opens by p / Cn, and the top rises by p h / E1 + p h / E2 + p / Cn (nu = 0: the
  // blocks do not contract sideways, or the glue would shear between them).
  const double p = 2.0, Cn = 400.0, h = 2.0;
  for (const char* element : {"1", "0"}) {
    std::ostringstream text;
    text << R"(bodies = ( { name = "lower"; material = { E = 1000.0; nu = 0.0; }; },
                          { name = "upper"; material = { E = 3000.0; nu = 0.0; }; } );
interface = {)" << glue << "Cn = " << Cn << R"(; };
loads = ( { node_set = "bottom"; type = "displacement"; component = "y"; value = 0.0; },
          { node_set = "lower_left"; type = "displacement"; component = "x"; value = 0.0; },
          { node_set = "upper_left"; type = "displacement"; component = "x"; value = 0.0; },
          { node_set = "top"; type = "pressure"; value = )" << -p << R"(; } );
time = { T = 1.0; };
integrator = { method = "contact-only"; };
)";
    const Config cfg = two_blocks(text.str(), {std::string("mesh.parameters={quads=") + element + ";}"});
    const Model model = test::make_model(cfg);
    RunOptions o;
    InterfaceState last;
    o.observer = [&](const AcceptedStep& a) { last = a.state; };
    Simulation(cfg, o).run();
    INFO((element[0] == '1' ? "Q4" : "T3"));
    const Layout& L = model.interface().layout;
    for (int i = 0; i < model.contact_nodes(); ++i) {
      CHECK(last.u[L.normal(i)] == Approx(p / Cn).epsilon(1e-9));            // the glue opens by p / Cn
      CHECK(std::abs(last.u[L.offset(i)]) <= 1e-9 * p / Cn);                   // and does not slide
      CHECK(model.interface().pairs[i].frame.n.isApprox(Eigen::Vector3d(0, 1, 0)));  // from lower (B) into upper (A)
    }
    const Eigen::VectorXd u = body_state(model, last).u;
    const double rise = p * h / 1000.0 + p * h / 3000.0 + p / Cn;
    for (double x : {0.0, 3.0, 10.0}) {
      CHECK(at(model, u, x, 4.0)[1] == Approx(rise).epsilon(1e-9));
      CHECK(at(model, u, x, 2.0)[1] == Approx(p * h / 1000.0).epsilon(1e-9));  // the lower block's top
    }
  }
}

TEST_CASE("two blocks glued by a stiff interface are one block, to a penalty error that shrinks as C grows",
          "[bodies]") {
  // The same 10 x 4 block as one body (the rectangle) and as two glued bodies, bonded to a
  // rigid base and pulled up and sideways at the top.
  const std::string common = R"(
material = { E = 1000.0; nu = 0.3; };
loads = ( { node_set = "top"; type = "traction"; component = "y"; value = 1.0; },
          { node_set = "top"; type = "traction"; component = "x"; value = 0.5; } );
time = { T = 1.0; };
integrator = { method = "contact-only"; };
)";
  const std::string base = R"(boundary = "bottom"; normal = [0.0, 1.0]; Cn = 1e4; Ct = 1e4; w = 1e9; mu = 0.3;)";
  const Config one_cfg = test::config_from_text(
      "mesh = { size = [10.0, 4.0]; nx = 10; ny = 4; element = \"Q4\"; };\ninterface = {" + base + "};\n" + common);
  const Model one = test::make_model(one_cfg);
  const Eigen::VectorXd u_one = displacement_at_T(one_cfg);
  std::vector<double> errors;
  for (double C : {1e4, 1e5, 1e6, 1e7}) {
    std::ostringstream glued;
    glued << "interfaces = ( {" << base << "}, { boundary = \"upper_bottom\"; opposite = \"lower_top\"; Cn = " << C
          << "; Ct = " << C << "; w = 1e9; mu = 0.3; } );\n";
    const Config cfg = two_blocks(glued.str() + common);
    const Model two = test::make_model(cfg);
    const Eigen::VectorXd u_two = displacement_at_T(cfg);
    double e = 0;
    for (double x : {0.0, 5.0, 10.0}) e = std::max(e, (at(two, u_two, x, 4.0) - at(one, u_one, x, 4.0)).norm());
    errors.push_back(e / at(one, u_one, 10.0, 4.0).norm());
  }
  INFO("relative errors " << errors[0] << " " << errors[1] << " " << errors[2] << " " << errors[3]);
  for (std::size_t k = 1; k < errors.size(); ++k) CHECK(errors[k] == Approx(errors[k - 1] / 10).epsilon(0.1));  // O(1/C)
  CHECK(errors.back() < 1e-4);
}

TEST_CASE("several interfaces: a symmetric problem stays symmetric, and a rotated one is the same", "[bodies]") {
  // Two glued blocks on a rigid base (two interfaces), pulled off by a uniform suction on
  // the top: symmetric about x = 5, and the same in every orientation (the base's normal
  // turns with the mesh). The glue is weaker than the base: it debonds from its ends.
  const auto run = [](double degrees) {
    const double a = degrees * M_PI / 180;
    std::ostringstream text;
    text << std::setprecision(17) << std::showpoint << "material = { E = 1000.0; nu = 0.3; };\n"
         << "interfaces = ( { boundary = \"bottom\"; normal = [" << -std::sin(a) << ", " << std::cos(a)
         << "]; Cn = 1e4; Ct = 1e4; w = 1.0; alpha = 1.0; mu = 0.3; },\n"
         << "  { boundary = \"upper_bottom\"; opposite = \"lower_top\"; Cn = 1e3; Ct = 1e3; w = 0.01; alpha = 1.0; "
            "mu = 0.3; } );\n"
         << "loads = ( { node_set = \"top\"; type = \"pressure\"; value = -5.0; } );\n"
         << "time = { T = 1.0; };\n";
    return Simulation(two_blocks(text.str(), {"mesh.rotation=" + std::to_string(degrees)})).run().snapshots.back();
  };
  const Snapshot s0 = run(0.0);
  // The glue's pairs run from x = 0 to 10 (11 pairs after the base's 11): pair k mirrors 10 - k.
  const Eigen::VectorXd beta = s0.beta.tail(11), u = s0.u.tail(22);
  REQUIRE(beta.minCoeff() < 1 - 1e-3);  // the glue has begun to debond
  REQUIRE(s0.beta.head(11).minCoeff() > beta.minCoeff());
  for (int k = 0; k <= 10; ++k) {
    INFO("glue pair " << k);
    CHECK(beta[k] == Approx(beta[10 - k]).epsilon(1e-7));
    CHECK(u[2 * k + 1] == Approx(u[2 * (10 - k) + 1]).epsilon(1e-7));        // u_n symmetric
    CHECK(u[2 * k] == Approx(-u[2 * (10 - k)]).margin(1e-7 * u.cwiseAbs().maxCoeff()));  // u_t antisymmetric
  }
  for (double degrees : {30.0, 90.0, 217.0}) {
    const Snapshot s = run(degrees);
    INFO(degrees << " degrees");
    CHECK((s.beta - s0.beta).cwiseAbs().maxCoeff() <= 1e-8);
    CHECK((s.u - s0.u).cwiseAbs().maxCoeff() <= 1e-8 * s0.u.cwiseAbs().maxCoeff());
    CHECK((s.Rbar - s0.Rbar).cwiseAbs().maxCoeff() <= 1e-8 * std::max(1.0, s0.Rbar.cwiseAbs().maxCoeff()));
  }
}

TEST_CASE("a precrack: the interface's nodes whose edges all lie in its node set start unbonded", "[bodies]") {
  // The edges of x in [0, 3] on the glue line: nodes 0, 1, 2 unbonded; the crack-tip node
  // x = 3 keeps its bonded edge.
  const Model m = test::make_model(two_blocks(R"(material = { E = 1000.0; nu = 0.3; };
interface = { boundary = "upper_bottom"; opposite = "lower_top"; precrack = "crack"; Cn = 1e3; Ct = 1e3; w = 1.0; mu = 0.3; };
loads = ( { node_set = "bottom"; type = "displacement"; component = "y"; value = 0.0; },
          { node_set = "bottom"; type = "displacement"; component = "x"; value = 0.0; } );
time = { T = 1.0; };
)", {"mesh.node_sets=({name=\"crack\";box=[0.0,3.0,2.0,2.0];})"}));
  const Eigen::VectorXd beta0 = m.initial_beta();
  for (int i = 0; i < m.contact_nodes(); ++i)
    CHECK(beta0[i] == (m.mesh().nodes[m.interface().pairs[i].node].x() < 2.5 ? 0.0 : 1.0));
}

TEST_CASE("a probe beside the glue line probes the body it lies in, though the node there is shared", "[bodies]") {
  // (5, 1.9) in the lower block and (5, 2.1) in the upper one are nearest to the glue line's
  // point (5, 2), where each block has its own node: each probe takes its own block's.
  const Model m = test::make_model(two_blocks(R"(material = { E = 1000.0; nu = 0.3; };
interface = { boundary = "upper_bottom"; opposite = "lower_top"; Cn = 1e3; Ct = 1e3; w = 1.0; mu = 0.3; };
loads = ( { node_set = "bottom"; type = "displacement"; component = "y"; value = 0.0; },
          { node_set = "bottom"; type = "displacement"; component = "x"; value = 0.0; } );
time = { T = 1.0; };
output = { probes = ( { name = "below"; point = [5.0, 1.9]; }, { name = "above"; point = [5.0, 2.1]; } ); };
)"));
  const Mesh& mesh = m.mesh();
  const auto body_of = [&](int node) {
    for (std::size_t c = 0; c < mesh.cells.size(); ++c)
      if (std::find(mesh.cells[c].begin(), mesh.cells[c].end(), node) != mesh.cells[c].end())
        return mesh.body_names[mesh.cell_body[c]];
    return std::string();
  };
  REQUIRE(m.probes().size() == 2);
  for (int k : {0, 1}) {
    CHECK((mesh.nodes[m.probes()[k]] - Eigen::Vector3d(5, 2, 0)).norm() < 1e-9);  // gmsh's coordinates
    CHECK(body_of(m.probes()[k]) == (k == 0 ? "lower" : "upper"));
  }
}

TEST_CASE("a probe beside a crack inside one body probes the side it lies in", "[bodies]") {
  // tests/meshes/cracked_plate_v22.msh: four Q4 of one body on [0, 2] x [0, 2], the edge from
  // (0, 1) to (1, 1) cracked: (0, 1) is node 4 of the lower-left cell and node 10 of the
  // upper-left one. (0, 0.9) lies below the crack, (0.05, 1.1) above; (0, 1) on it.
  const auto probe_in = [](const std::string& file, const std::string& at) {
    return test::config_from_text("mesh = { file = \"" + std::string(RCCM_SOURCE_DIR) + "/tests/meshes/" + file + R"("; };
material = { E = 1000.0; nu = 0.3; };
interface = { boundary = "bottom"; Cn = 1e3; Ct = 1e3; w = 1.0; mu = 0.3; };
loads = ( { node_set = "plate"; type = "force"; component = "y"; value = 0.0; } );
time = { T = 1.0; };
output = { probes = ( { name = "p"; point = )" + at + "; } ); };\n");
  };
  const auto with_probe = [&](const std::string& at) { return probe_in("cracked_plate_v22.msh", at); };
  for (const auto& [at, below] : {std::pair<std::string, bool>{"[0.0, 0.9]", true}, {"[0.05, 1.1]", false}}) {
    INFO(at);
    const Model m = test::make_model(with_probe(at));
    REQUIRE(m.probes().size() == 1);
    const Mesh& x = m.mesh();
    const int node = m.probes()[0];
    CHECK((x.nodes[node] - Eigen::Vector3d(0, 1, 0)).norm() < 1e-12);
    // the node is a corner of the cell on the point's side and not of the other one
    const auto corner_of_cell_at = [&](double y) {
      const std::vector<int> cells = x.cells_holding({0.5, y, 0});
      REQUIRE(cells.size() == 1);
      const std::vector<int>& cell = x.cells[cells[0]];
      return std::find(cell.begin(), cell.end(), node) != cell.end();
    };
    CHECK(corner_of_cell_at(0.5) == below);
    CHECK(corner_of_cell_at(1.5) == !below);
  }
  CHECK_THROWS_WITH(test::make_model(with_probe("[0.0, 1.0]")),
                    Catch::Contains("(they share that point), and lies on the crack between them, in body 'plate'; move it "
                                    "into the body, or the side of the crack, you mean"));
  // tests/meshes/thin_crack_v22.msh: a crack along y = 0 whose middle node (0, 0) is node 2
  // below and 8 above, flat triangles beside it. (0, 0.05) lies in a triangle of node 8;
  // (0, 0.15), though nearest to (0, 0), in a triangle with neither as a corner: refused, saying so.
  const auto thin_probe = [&](const std::string& at) { return probe_in("thin_crack_v22.msh", at); };
  const Model near = test::make_model(thin_probe("[0.0, 0.05]"));
  REQUIRE(near.probes().size() == 1);
  CHECK(near.mesh().nodes[near.probes()[0]].norm() < 1e-12);
  const std::vector<int> above = near.mesh().cells_holding({0.0, 0.05, 0});
  REQUIRE(above.size() == 1);
  const std::vector<int>& cell = near.mesh().cells[above[0]];
  CHECK(std::find(cell.begin(), cell.end(), near.probes()[0]) != cell.end());
  CHECK_THROWS_WITH(test::make_model(thin_probe("[0.0, 0.15]")),
                    Catch::Contains("lies in a cell with neither as a corner; move it nearer the node you mean") &&
                        !Catch::Contains("side of the crack"));
}

TEST_CASE("bodies and body-body interfaces that cannot be are refused, naming the setting and the node", "[bodies]") {
  const std::string rest = R"(
loads = ( { node_set = "top"; type = "displacement"; component = "y"; value = 0.1; },
          { node_set = "bottom"; type = "displacement"; component = "y"; value = 0.0; },
          { node_set = "bottom"; type = "displacement"; component = "x"; value = 0.0; } );
time = { T = 1.0; };
)";
  const std::string material = "material = { E = 1000.0; nu = 0.3; };\n";
  const auto refused = [](const Config& cfg, const std::string& expect) {
    CHECK_THROWS_WITH(test::make_model(cfg), Catch::Contains(expect));
  };
  // A body without a material; a misspelt name (the nearest one suggested).
  refused(two_blocks("bodies = ( { name = \"lower\"; material = { E = 1.0; nu = 0.3; }; } );\ninterface = {" + glue +
                     "Cn = 1e3; };" + rest),
          "bodies: the mesh's body 'upper' has no material");
  refused(two_blocks("bodies = ( { name = \"lower\"; material = { E = 1.0; nu = 0.3; }; }, { name = \"uper\"; material "
                     "= { E = 1.0; nu = 0.3; }; } );\ninterface = {" + glue + "Cn = 1e3; };" + rest),
          "bodies.[1].name: the mesh has no body named 'uper'; did you mean 'upper'?");  // the typo, not its consequence
  // Meshes that do not match along the interface: the worst node is named.
  refused(two_blocks(material + "interface = { boundary = \"upper_bottom\"; opposite = \"bottom\"; Cn = 1e3; Ct = 1e3; "
                                "w = 1.0; mu = 0.3; };" + rest),
          "the meshes of 'upper_bottom' and 'bottom' do not match: node (0, 2) of 'upper_bottom' is 2 mm from the "
          "nearest node of 'bottom'");
  refused(two_blocks(material + "interface = { boundary = \"upper_bottom\"; opposite = \"lower_left\"; Cn = 1e3; Ct = "
                                "1e3; w = 1.0; mu = 0.3; };" + rest),
          "the meshes of 'upper_bottom' and 'lower_left' do not match: 'lower_left' has 3 nodes, 'upper_bottom' 11; "
          "the meshes along the interface must match node for node");
  // One node on two interfaces.
  refused(two_blocks(material + "interfaces = ( {" + glue + "Cn = 1e3; }, { boundary = \"upper_left\"; normal = [1.0, "
                                "0.0]; Cn = 1.0; Ct = 1.0; w = 1.0; mu = 0.3; } );" + rest),
          "is on interfaces.[0] already: a node belongs to one interface");
  // A body-body interface with a gap setting, a tolerance on a rigid line.
  CHECK_THROWS_WITH(two_blocks(material + "interface = {" + glue + "Cn = 1e3; g0 = 0.1; };" + rest),
                    Catch::Contains("interface.g0: the gap of a circle or of two bodies comes from their geometry"));
  CHECK_THROWS_WITH(two_blocks(material + "interface = { boundary = \"bottom\"; tolerance = 0.1; Cn = 1.0; Ct = 1.0; w "
                                          "= 1.0; mu = 0.3; };" + rest),
                    Catch::Contains("interface.tolerance: applies to an interface between two bodies"));
}

TEST_CASE("both sides of a body-body interface prescribed: an opening runs, a closing is refused", "[bodies]") {
  // The gap's change is u_n = n . (u_upper - u_lower): each side's displacement counts, and
  // one side prescribed alone fixes no gap (the other body gives way).
  const auto sides = [](double upper, const std::string& lower) {
    const std::string y = "type = \"displacement\"; component = \"y\"; value = ";
    return two_blocks("material = { E = 1000.0; nu = 0.3; };\ninterface = {" + glue + "Cn = 1e3; };\n" +
                      "loads = ( { node_set = \"upper_bottom\"; " + y + std::to_string(upper) + "; },\n" +
                      (lower.empty() ? "" : " { node_set = \"lower_top\"; " + y + lower + "; },\n") +
                      " { node_set = \"bottom\"; type = \"displacement\"; component = \"x\"; value = 0.0; } );\n"
                      "time = { T = 1.0; };\n");
  };
  CHECK_NOTHROW(test::make_model(sides(0.05, "0.02")));
  CHECK_NOTHROW(test::make_model(sides(-0.02, "")));
  CHECK_THROWS_WITH(test::make_model(sides(0.02, "0.05")),
                    Catch::Contains("loads: the prescribed displacements push contact node 0 (0, 2) into the other body "
                                    "(its mesh node ") &&
                        Catch::Contains("by 0.03 mm at t = 1 s"));
}

TEST_CASE("a physical group of two curves or surfaces loads and bonds its own elements only", "[bodies]") {
  // A 10 x 2 plate one cell thick (Q4, 10 x 1): the group "faces" holds its bottom and top
  // curves, whose nodes also end the one-cell sides x = 0 and x = 10. A traction x = 1 MPa
  // on "faces" carries 2 x 10 mm x 1 MPa = 20 N; the sides (2 x 2 mm) are not its elements.
  const std::string plate = test::write_temp_file("faces_plate.geo", R"(
Point(1) = {0, 0, 0}; Point(2) = {10, 0, 0}; Point(3) = {10, 2, 0}; Point(4) = {0, 2, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 11; Transfinite Curve{2, 4} = 2; Transfinite Surface{1}; Recombine Surface{1};
Physical Surface("plate") = {1}; Physical Curve("bottom") = {1}; Physical Curve("faces") = {1, 3};
)");
  const std::string law = "Cn = 1e3; Ct = 1e3; w = 10.0; alpha = 0.1; mu = 0.3;";
  const auto model = [&](const std::string& mesh, const std::string& boundary, const std::string& load, int dim = 2) {
    return test::make_model(test::config_from_text("mesh = { file = \"" + mesh + "\"; };\n"
                                                   "material = { E = 1000.0; nu = 0.3; };\n"
                                                   "interface = { boundary = \"" + boundary + "\"; normal = [0.0, 1.0" +
                                                   (dim == 2 ? "" : ", 0.0") + "]; " + law + " };\n"
                                                   "loads = ( " + load + " );\ntime = { T = 1.0; };\n"));
  };
  const auto resultant = [](const Model& m, int component) {
    double sum = 0;
    for (int n = 0; n < m.mesh().num_nodes(); ++n) sum += m.loads()[0].force[m.mesh().dof(n, component)];
    return sum;
  };
  const std::string traction_x = R"({ node_set = "faces"; type = "traction"; component = "x"; value = 1.0; })";
  CHECK(resultant(model(plate, "bottom", traction_x), 0) == Approx(20.0).epsilon(1e-14));
  // A pressure on both faces pushes along y only: no x force at the ends' nodes (the ends'
  // edges, loaded too, pushed each end node by 1 N along x).
  const Model pressed = model(plate, "bottom", R"({ node_set = "faces"; type = "pressure"; value = 1.0; })");
  for (int n = 0; n < pressed.mesh().num_nodes(); ++n) CHECK(pressed.loads()[0].force[pressed.mesh().dof(n, 0)] == 0.0);
  CHECK(std::abs(resultant(pressed, 1)) <= 1e-12);

  // An interface on two parts of the base, x in [0, 3] and [7, 10], the 4 mm between them one
  // cell long: 6 mm bonded, a = 0.25 mm at x = 3 and x = 7 (half of their one bonded edge), and
  // the interface's facets (its .vtp cells) are the group's 12 edges (6 per stretch).
  const std::string split = test::write_temp_file("split_base.geo", R"(
Point(1) = {0, 0, 0}; Point(2) = {3, 0, 0}; Point(3) = {7, 0, 0}; Point(4) = {10, 0, 0};
Point(5) = {10, 2, 0}; Point(6) = {0, 2, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5}; Line(5) = {5, 6}; Line(6) = {6, 1};
Curve Loop(1) = {1, 2, 3, 4, 5, 6}; Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 7; Transfinite Curve{2} = 2;
Physical Surface("plate") = {1}; Physical Curve("glue") = {1, 3}; Physical Curve("faces") = {5};
)");
  const Model glued = model(split, "glue", traction_x);
  double bonded = 0;
  for (const ContactPair& c : glued.interface().pairs) {
    bonded += c.measure;
    const double x = glued.mesh().nodes[c.node].x();
    if (std::abs(x - 3) < 1e-12 || std::abs(x - 7) < 1e-12) CHECK(c.measure == Approx(0.25).margin(1e-9));
  }
  CHECK(bonded == Approx(6.0).margin(1e-9));
  CHECK(glued.interface().facets.size() == 12);

  // 3D: a 4 x 0.5 x 3 plate one H8 thick, "faces" its base and top: a traction x on them
  // carries 2 x 12 mm^2 x 1 MPa = 24 N, not the four sides' 7 mm^2 more.
  const std::string slab = test::write_temp_file("faces_slab.geo", R"(
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 4, 0.5, 3};
Transfinite Curve{:} = 3;
e = 1e-6;
Transfinite Curve{Curve In BoundingBox{-e, -e, -e, e, 0.5 + e, e}, Curve In BoundingBox{4 - e, -e, -e, 4 + e, 0.5 + e, e},
                  Curve In BoundingBox{-e, -e, 3 - e, e, 0.5 + e, 3 + e}, Curve In BoundingBox{4 - e, -e, 3 - e, 4 + e, 0.5 + e, 3 + e}} = 2;
Transfinite Surface{:}; Recombine Surface{:}; Transfinite Volume{:};
Physical Volume("plate") = {1};
Physical Surface("base") = Surface In BoundingBox{-e, -e, -e, 4 + e, e, 3 + e};
Physical Surface("faces") = {Surface In BoundingBox{-e, -e, -e, 4 + e, e, 3 + e}, Surface In BoundingBox{-e, 0.5 - e, -e, 4 + e, 0.5 + e, 3 + e}};
)");
  CHECK(resultant(model(slab, "base", traction_x, 3), 0) == Approx(24.0).epsilon(1e-13));
}

TEST_CASE("two bodies apart or overlapping by what a raised tolerance let through: a gap noted and an overlap refused", "[bodies]") {
  // tests/meshes/two_blocks.geo with the upper block raised by 0.01 mm: refused at the default
  // tolerance (1e-3 of the shortest edge, 1 mm), matched with interface.tolerance = 0.02, and
  // then each bonded pair's spring acts across the gap: noted, the largest gap named.
  std::ifstream in(fixture);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string flush = "Point(5) = {0, h, 0}; Point(6) = {L, h, 0}; Point(7) = {L, 2 * h, 0}; Point(8) = {0, 2 * h, 0};";
  REQUIRE(text.find(flush) != std::string::npos);
  const auto moved = [&](const std::string& name, const std::string& dy) {
    std::string geo = text;
    geo.replace(geo.find(flush), flush.size(),
                "Point(5) = {0, h + " + dy + ", 0}; Point(6) = {L, h + " + dy + ", 0}; Point(7) = {L, 2 * h + " + dy +
                    ", 0}; Point(8) = {0, 2 * h + " + dy + ", 0};");
    return test::write_temp_file(name, geo);
  };
  const std::string raised = moved("two_blocks_gap.geo", "0.01");
  const auto glued = [&](const std::string& mesh, const std::string& extra) {
    const Config cfg = test::config_from_text("mesh = { file = \"" + mesh + "\"; };\nmaterial = { E = 1000.0; nu = 0.3; };\n"
                                              "interface = {" + glue + "Cn = 1e3; " + extra + " };\n"
                                              "loads = ( { node_set = \"top\"; type = \"force\"; component = \"y\"; value = 0.1; } );\n"
                                              "time = { T = 1.0; };\n");
    return make_interface(make_mesh(cfg), cfg).notes;
  };
  CHECK_THROWS_WITH(glued(raised, ""), Catch::Contains("raise interface.tolerance"));
  const std::vector<std::string> notes = glued(raised, "tolerance = 0.02;");
  REQUIRE(notes.size() == 1);
  CHECK_THAT(notes[0], Catch::Contains("11 contact node(s) start bonded across a gap, up to g0 = 0.01 mm") &&
                           Catch::Contains("a bonded interface touches the other body"));
  CHECK(glued(raised, "tolerance = 0.02; beta0 = 0.0;").empty());  // open from the start: contact across a gap
  CHECK(glued(fixture, "tolerance = 0.02;").empty());              // the blocks touch
  // Lowered into the lower block instead: contact would push the bodies apart at once.
  CHECK_THROWS_WITH(glued(moved("two_blocks_overlap.geo", "-0.01"), "tolerance = 0.02;"),
                    Catch::Contains("the bodies overlap by 0.01 mm ('upper_bottom' lies inside 'lower_top')"));
}

TEST_CASE("an interface on a curve two bodies share is refused saying their meshes are fused there", "[bodies]") {
  // Two rectangles meshed on one shared curve (as BooleanFragments leaves them): the curve's
  // edges lie inside the mesh, an interface there has no boundary edge to bond.
  const std::string fused = test::write_temp_file("fused.geo", R"(
Point(1) = {0, 0, 0, 1}; Point(2) = {4, 0, 0, 1}; Point(3) = {4, 1, 0, 1}; Point(4) = {0, 1, 0, 1};
Point(5) = {4, 2, 0, 1}; Point(6) = {0, 2, 0, 1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1}; Line(5) = {3, 5}; Line(6) = {5, 6}; Line(7) = {6, 4};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {-3, 5, 6, 7}; Plane Surface(2) = {2};
Physical Surface("lower") = {1}; Physical Surface("upper") = {2}; Physical Curve("glue") = {3}; Physical Curve("base") = {1};
)");
  const Config cfg = test::config_from_text("mesh = { file = \"" + fused + "\"; };\nmaterial = { E = 1000.0; nu = 0.3; };\n"
                                            "interface = { boundary = \"glue\"; normal = [0.0, 1.0]; Cn = 1e3; Ct = 1e3; w = 1.0; mu = 0.3; };\n"
                                            "loads = ( { node_set = \"base\"; type = \"displacement\"; component = \"y\"; value = 0.0; } );\n"
                                            "time = { T = 1.0; };\n");
  CHECK_THROWS_WITH(test::make_model(cfg), Catch::Contains("is on none of the set's own edges (bodies 'lower' and 'upper' share "
                                                           "this node: their meshes are fused there") &&
                                               Catch::Contains("set interface.opposite"));
}

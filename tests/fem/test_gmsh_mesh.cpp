// The gmsh mesh source (fem/gmsh_mesh): the same geometry from a .geo, MSH 2.2 and MSH 4.1
// gives the same mesh; bodies, node sets, boundary facets and orientation follow from the
// physical groups; a bad mesh file is refused naming the file and the physical group;
// rccm-gmsh, which reads them, answers a caller of another build that it is one.
#include "helpers.hpp"
#include "rccm/base/child_process.hpp"
#include "rccm/base/errors.hpp"
#include "rccm/fem/gmsh_mesh.hpp"
#include "rccm/fem/mesh_bytes.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <optional>
#include <unistd.h>

using namespace rccm;
namespace fs = std::filesystem;

namespace {

const std::string fixtures = std::string(RCCM_SOURCE_DIR) + "/tests/meshes/";

Mesh read(const std::string& file, int refine = 0, std::map<std::string, double> parameters = {}) {
  MeshParams p;
  p.file = file;
  p.refine = refine;
  p.parameters = std::move(parameters);
  return read_gmsh(p, "test.cfg:1: mesh.file");
}

/// A .geo file with `text`.
std::string geo(const std::string& name, const std::string& text) { return test::write_temp_file(name, text); }

double area(const Mesh& m, const std::vector<int>& cell) {
  double a2 = 0;
  for (std::size_t k = 0; k < cell.size(); ++k) {
    const Eigen::Vector3d &p = m.nodes[cell[k]], &q = m.nodes[cell[(k + 1) % cell.size()]];
    a2 += p.x() * q.y() - q.x() * p.y();
  }
  return a2 / 2;
}

const char* square = R"(
Point(1) = {0, 0, 0, 0.5}; Point(2) = {2, 0, 0, 0.5}; Point(3) = {2, 1, 0, 0.5}; Point(4) = {0, 1, 0, 0.5};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
)";

}  // namespace

TEST_CASE("gmsh: a .geo and its MSH 2.2 and 4.1 files are the same mesh, with bodies and node sets from the groups",
          "[gmsh]") {
  const Mesh g = read(fixtures + "two_blocks.geo");
  for (const char* file : {"two_blocks_v22.msh", "two_blocks_v41.msh"}) {
    INFO(file);
    const Mesh m = read(fixtures + file);
    REQUIRE(m.num_nodes() == g.num_nodes());
    REQUIRE(m.cells.size() == g.cells.size());
    CHECK(m.body_names == g.body_names);
    CHECK(m.node_set_names() == g.node_set_names());
    for (int n = 0; n < m.num_nodes(); ++n) CHECK((m.nodes[n] - g.nodes[n]).norm() <= 1e-14);
  }
  // Two bodies of 10 x 2 in Q4 cells (10 x 2 each), counter-clockwise, covering 40 mm^2.
  CHECK(g.body_names == std::vector<std::string>{"lower", "upper"});
  REQUIRE(g.cells.size() == 40);
  double total = 0, lower = 0;
  for (std::size_t c = 0; c < g.cells.size(); ++c) {
    CHECK(g.cells[c].size() == 4);
    CHECK(area(g, g.cells[c]) > 0);
    total += area(g, g.cells[c]);
    if (g.cell_body[c] == 0) lower += area(g, g.cells[c]);
  }
  CHECK(total == Approx(40.0).epsilon(1e-12));
  CHECK(lower == Approx(20.0).epsilon(1e-12));
  // The blocks have their own nodes along y = 2: 2 x 33 nodes, and each block's boundary
  // (the glued edges included) is boundary: 2 x (10 + 2) x 2 facets.
  CHECK(g.num_nodes() == 66);
  CHECK(g.facets.size() == 48);
  // Node sets: a curve's nodes in order along it, a point's one node, a body's all nodes.
  const std::vector<int>& top = g.node_set("lower_top");
  REQUIRE(top.size() == 11);
  for (std::size_t k = 1; k < top.size(); ++k)
    CHECK(std::abs(g.nodes[top[k]].x() - g.nodes[top[k - 1]].x()) == Approx(1.0));
  for (int n : top) CHECK(g.nodes[n].y() == Approx(2.0));
  for (int n : g.node_set("upper_bottom")) CHECK(std::find(top.begin(), top.end(), n) == top.end());
  REQUIRE(g.node_set("corner").size() == 1);
  CHECK(g.nodes[g.node_set("corner")[0]].isApprox(Eigen::Vector3d(10, 4, 0)));
  CHECK(g.node_set("upper").size() == 33);
  // The boundary edges of a curve carry the outward normal of their body.
  for (const BoundaryEdge& e : g.boundary_edges(g.facets_of("lower_top"))) CHECK(e.outward.isApprox(Eigen::Vector3d(0, 1, 0)));
  for (const BoundaryEdge& e : g.boundary_edges(g.facets_of("upper_bottom")))
    CHECK(e.outward.isApprox(Eigen::Vector3d(0, -1, 0)));
}

TEST_CASE("gmsh: parameters of a .geo, triangles, uniform refinement", "[gmsh]") {
  const Mesh t = read(fixtures + "two_blocks.geo", 0, {{"quads", 0.0}, {"L", 20.0}});
  CHECK(t.cells.size() == 80);  // 2 triangles per quad
  for (const auto& c : t.cells) CHECK(c.size() == 3);
  double total = 0;
  for (const auto& c : t.cells) total += area(t, c);
  CHECK(total == Approx(80.0).epsilon(1e-12));
  const Mesh r = read(fixtures + "two_blocks.geo", 2);
  CHECK(r.cells.size() == 40 * 16);
  CHECK(r.node_set("lower_top").size() == 41);
  double refined = 0;
  for (const auto& c : r.cells) {
    refined += area(r, c);
    CHECK(area(r, c) > 0);
  }
  CHECK(refined == Approx(40.0).epsilon(1e-12));
}

TEST_CASE("gmsh: a clockwise surface is turned counter-clockwise", "[gmsh]") {
  // The curve loop runs clockwise: gmsh orients the cells along it.
  const Mesh m = read(geo("cw.geo", R"(
Point(1) = {0, 0, 0, 0.5}; Point(2) = {2, 0, 0, 0.5}; Point(3) = {2, 1, 0, 0.5}; Point(4) = {0, 1, 0, 0.5};
Line(1) = {1, 4}; Line(2) = {4, 3}; Line(3) = {3, 2}; Line(4) = {2, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Physical Surface("body") = {1};
)"));
  REQUIRE(!m.cells.empty());
  double total = 0;
  for (const auto& c : m.cells) {
    CHECK(area(m, c) > 0);
    total += area(m, c);
  }
  CHECK(total == Approx(2.0).epsilon(1e-12));
}

TEST_CASE("gmsh: a mesh too fine for the memory is refused before meshing and a graded structured one is not", "[gmsh]") {
  // Uniformly tiny, on a rectangle split into five curves (a point on its top side): 1.15 A / h^2
  // nodes, 2 unknowns each: 2 x 1.15 x 20 / 1e-8 = 4.6e9; on four curves, the grid they make:
  // 2 x (1e5 + 1) x (2e4 + 1) = 4.0e9.
  const auto plate = [](const std::string& name, const std::string& top) {
    return geo(name, R"(
DefineConstant[ h = {0.5, Name "h"} ];
Point(1) = {0, 0, 0}; Point(2) = {10, 0, 0}; Point(3) = {10, 2, 0}; Point(4) = {0, 2, 0}; Point(5) = {5, 2, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(4) = {4, 1};
)" + top + R"(
Plane Surface(1) = {1};
Mesh.MeshSizeMin = h; Mesh.MeshSizeMax = h;
Physical Surface("plate") = {1};
)");
  };
  const std::string five = plate("five.geo", "Line(3) = {3, 5}; Line(5) = {5, 4}; Curve Loop(1) = {1, 2, 3, 5, 4};");
  const std::string four = plate("four.geo", "Line(3) = {3, 4}; Curve Loop(1) = {1, 2, 3, 4};");
  CHECK_THROWS_WITH(read(five, 0, {{"h", 1e-4}}), Catch::Contains("meshing it (about 4.6e+09 unknowns) needs about"));
  CHECK_THROWS_WITH(read(four, 0, {{"h", 1e-4}}), Catch::Contains("meshing it (about 4e+09 unknowns) needs about"));
  CHECK(read(five, 0, {{"h", 0.5}}).num_nodes() > 0);
  // The double cantilever beam's arms, 0.005 mm cells along the interface and 6 through an arm
  // (Transfinite): a uniform fill would ask 5e7 unknowns; each arm is (25 + 1000 + 8000 + 30 + 1) x 7 nodes.
  const Mesh dcb = read(std::string(RCCM_SOURCE_DIR) + "/config/dcb.geo", 0, {{"dx", 0.005}});
  CHECK(dcb.num_nodes() == 2 * 9056 * 7);
}

TEST_CASE("gmsh: a bad mesh file is refused, naming the file and the physical group", "[gmsh]") {
  const auto refused = [](const std::string& file, const std::string& expect, std::map<std::string, double> parameters = {}) {
    INFO(file);
    CHECK_THROWS_WITH(read(file, 0, parameters), Catch::Contains("test.cfg:1: mesh.file: " + file) && Catch::Contains(expect));
  };
  refused(geo("no_bodies.geo", std::string(square)), "no Physical Surface");
  refused(geo("unnamed.geo", std::string(square) + "Physical Surface(\"a\") = {1};\nPoint(9) = {5, 5, 0};\nPhysical Point(\"far\") = {9};\n"),
          "Physical Point 'far' has a node on no cell");
  refused(geo("quadratic.geo", std::string(square) + "Physical Surface(\"plate\") = {1};\nMesh.ElementOrder = 2;\nMesh 2;\n"),
          "Physical Surface 'plate' has Triangle 6 cells: rccm reads linear triangles (T3) and quadrangles (Q4); mesh with "
          "Mesh.ElementOrder = 1");
  // gmsh keeps one of the two types and drops the T6 silently: its own nodes are left in no cell.
  refused(fixtures + "mixed_t3_t6_v22.msh", "surface 1 of Physical Surface 'plate' holds 3 node(s) that no cell uses "
          "(node 7 at (1.5, 0)): gmsh may have dropped cells it read");
  // A concave Q4 (its corners (0, 0), (4, 0), (4, 4), (3, 1): counter-clockwise, of positive
  // area, but bent inward at (3, 1)) and an H8 whose bottom face is listed reversed, its top
  // not (turned positive at node 0 by the reader, it folds at another corner): no element.
  refused(fixtures + "concave_q4_v22.msh", "Physical Surface 'body' has a quadrangle that folds at its corner (3, 1)");
  refused(fixtures + "twisted_h8_v22.msh", "Physical Volume 'blk' has a hexahedron that folds at its corner");
  refused(geo("syntax.geo", "Point(1) = {0, 0, 0\n"), "syntax error");
  // A coordinate that is no number, or beyond what an assembly can square (as mesh.size).
  refused(fixtures + "node_z_nan.msh", "node 3 lies at (10, 2, nan): the mesh must lie within 1e15 mm of 0");
  refused(fixtures + "node_x_huge.msh", "node 2 lies at (1e+308, 0, 0): the mesh must lie within 1e15 mm of 0");
  refused(geo("clash.geo", std::string(square) + "Physical Surface(\"plate\") = {1};\nPhysical Curve(\"plate\") = {1};\n"),
          "Physical Curve 'plate' has the name of another physical group");
  refused(geo("left_out.geo", std::string(square) + R"(
Point(5) = {3, 0, 0, 0.5}; Point(6) = {4, 0, 0, 0.5}; Point(7) = {4, 1, 0, 0.5}; Point(8) = {3, 1, 0, 0.5};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};
Physical Surface("plate") = {1};
)"),
          "surface 2 is meshed but in no Physical Surface");
  refused(geo("tilted.geo", R"(
Point(1) = {0, 0, 0, 0.5}; Point(2) = {2, 0, 1, 0.5}; Point(3) = {2, 1, 1, 0.5}; Point(4) = {0, 1, 0, 0.5};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Physical Surface("plate") = {1};
)"),
          "a 2D mesh lies in the plane z = 0");
  refused(fixtures + "two_blocks.geo", "mesh.parameters.Lx: the file defines no such parameter", {{"Lx", 3.0}});
  // The file's own parameters listed, not gmsh's ONELAB entries.
  refused(fixtures + "two_blocks.geo", "mesh.parameters.foo: the file defines no such parameter (DefineConstant[ foo = "
          "{value, Name \"foo\"} ]); known here: L, h, n, quads", {{"foo", 3.0}});
  refused(fixtures + "two_blocks_v41.msh", "mesh.parameters set the DefineConstant values of a .geo file", {{"L", 3.0}});
  // gmsh aborts on it from its OpenMP threads: its process ends, ours reports it.
  refused(geo("point_size_negative.geo", R"(
Point(1) = {0, 0, 0, 1}; Point(2) = {10, 0, 0, -1}; Point(3) = {10, 2, 0, 1}; Point(4) = {0, 2, 0, 1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Physical Surface("layer") = {1};
)"),
          "gmsh stopped abnormally while reading or meshing the file (signal 6, Aborted): gmsh 4.8 aborts on errors it "
          "cannot report, most often a mesh size of 0 or below on a Point");
  // A MSH 2.2 file whose header was edited to another version: gmsh's message, then the format.
  const std::string v22 = test::read_text(fixtures + "two_blocks_v22.msh");
  REQUIRE(v22.find("$MeshFormat\n2.2 0 8\n") == 0);
  for (const char* version : {"4.0", "3.0"})
    refused(geo(std::string("header_") + version + ".msh", "$MeshFormat\n" + std::string(version) + v22.substr(15)),
            std::string("(its header states MSH ") + version + "; rccm reads MSH 2.2 and 4.1");
  refused(fixtures + "missing.msh", "cannot read the file");
  refused(fixtures + "../../config/b1.cfg", "a mesh file is a gmsh .msh or .geo file");
}

TEST_CASE("rccm-gmsh: a caller of another build is told so, not sent bytes it would misread", "[gmsh]") {
  const std::string caller = std::to_string(::getpid());
  const ChildOutcome other = run_program(RCCM_GMSH_PROGRAM, {caller, "w", "mesh", "0.0.0/0", fixtures + "two_blocks.geo", "0"});
  CHECK(other.finished);
  CHECK(other.bytes == "V" + mesh_bytes_protocol());
  // The same build: the dimension of a 2D file.
  const ChildOutcome same = run_program(RCCM_GMSH_PROGRAM, {caller, "", "dimension", mesh_bytes_protocol(), fixtures + "two_blocks.geo", "0"});
  CHECK(same.finished);
  CHECK(same.bytes == "M2");
}

TEST_CASE("GmshReuse: the same file, refinement and parameters read once, others read again", "[gmsh]") {
  const std::string file = geo("reused.geo", std::string(square) + "Physical Surface(\"plate\") = {1};\n");
  MeshParams p;
  p.file = file;
  p.contents = "hash of the text";
  std::optional<Mesh> first;
  {
    const GmshReuse reuse;
    first = read_gmsh(p, "test.cfg:1: mesh.file");
    CHECK(read_gmsh_dimension(p) == 2);
    fs::remove(file);  // gone: only an answer kept can give the mesh again
    const Mesh again = read_gmsh(p, "test.cfg:1: mesh.file");
    CHECK(again.nodes == first->nodes);
    CHECK(again.cells == first->cells);
    CHECK(again.node_sets == first->node_sets);
    CHECK(read_gmsh_dimension(p) == 2);
    // Another refinement, or other contents of the file, is another request: gmsh is asked.
    MeshParams refined = p, edited = p;
    refined.refine = 1;
    edited.contents = "another text";
    CHECK_THROWS_WITH(read_gmsh(refined, "test.cfg:1: mesh.file"), Catch::Contains("cannot read the file"));
    CHECK_THROWS_WITH(read_gmsh(edited, "test.cfg:1: mesh.file"), Catch::Contains("cannot read the file"));
  }
  // Without a GmshReuse nothing is kept.
  CHECK_THROWS_WITH(read_gmsh(p, "test.cfg:1: mesh.file"), Catch::Contains("cannot read the file"));
}

// How far the bodies are from small strains (fem/elasticity: SmallStrainCheck), against
// fields whose displacement gradient is known in closed form: a rigid rotation gives
// |grad u|_2 = 2 sin(theta / 2) in every cell (plane T3 and Q4, 3D H8 and T4, about any
// axis), an axisymmetric radial shift its hoop gradient u_r / r, and the share beyond a limit
// is counted by volume and per body.
#include "helpers.hpp"
#include "rccm/fem/box_mesh.hpp"
#include "rccm/fem/elasticity.hpp"
#include "rccm/fem/mesh.hpp"

#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

using namespace rccm;

namespace {

/// Each H8 of `m` as the six T4 of Kuhn's split along its diagonal 0-6, each of positive volume.
Mesh kuhn_tetrahedra(Mesh m) {
  static const int path[6][2] = {{1, 2}, {1, 5}, {3, 2}, {3, 7}, {4, 5}, {4, 7}};
  std::vector<std::vector<int>> cells;
  for (const std::vector<int>& h : m.cells)
    for (const auto& p : path) {
      std::vector<int> t = {h[0], h[p[0]], h[p[1]], h[6]};
      const Eigen::Vector3d &x0 = m.nodes[t[0]], &x1 = m.nodes[t[1]], &x2 = m.nodes[t[2]], &x3 = m.nodes[t[3]];
      if ((x1 - x0).cross(x2 - x0).dot(x3 - x0) < 0) std::swap(t[1], t[2]);
      cells.push_back(t);
    }
  m.cells = cells;
  m.cell_body.assign(cells.size(), 0);
  return m;
}

/// u = (R - I)(x - x0) at every node: a rigid rotation about x0.
Eigen::VectorXd rotated(const Mesh& m, const Eigen::Matrix3d& R, const Eigen::Vector3d& x0) {
  Eigen::VectorXd u(m.num_dofs());
  for (int n = 0; n < m.num_nodes(); ++n)
    u.segment(m.dof(n, 0), m.dim) = ((R - Eigen::Matrix3d::Identity()) * (m.nodes[n] - x0)).head(m.dim);
  return u;
}

/// The measure is exactly `expected` in every cell: the whole body lies beyond a limit just
/// below it and nothing beyond one just above it.
void check_uniform(const Mesh& m, const Eigen::VectorXd& u, double expected) {
  const DeformationExcess below = SmallStrainCheck(m)(u, expected * (1 - 1e-9));
  CHECK(below.largest == Approx(expected).epsilon(1e-12));
  CHECK(below.fraction == Approx(1.0).epsilon(1e-12));
  CHECK(below.body == 0);
  const DeformationExcess above = SmallStrainCheck(m)(u, expected * (1 + 1e-9));
  CHECK(above.fraction == 0.0);
  CHECK(above.body == -1);
}

}  // namespace

TEST_CASE("a rigid rotation by theta has |grad u| = 2 sin(theta/2) in every cell: T3 and Q4 in the plane", "[elasticity]") {
  for (bool triangles : {false, true})
    for (double theta : {0.05, 0.3, 1.2}) {
      INFO((triangles ? "T3" : "Q4") << ", theta = " << theta);
      const Mesh m = test::distorted_patch(triangles, false);
      const Eigen::Matrix3d R = Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitZ()).toRotationMatrix();
      check_uniform(m, rotated(m, R, {0.7, -2.0, 0.0}), 2 * std::sin(theta / 2));
    }
}

TEST_CASE("a rigid rotation by theta has |grad u| = 2 sin(theta/2) in every cell: H8 and T4 about any axis", "[elasticity]") {
  for (bool tetrahedra : {false, true}) {
    const Mesh box = make_box(test::box(2.0, 1.0, 3.0, 2, 2, 3));
    const Mesh m = tetrahedra ? kuhn_tetrahedra(box) : box;
    const char* element = tetrahedra ? "T4" : "H8";
    const Eigen::Matrix3d R = Eigen::AngleAxisd(0.4, Eigen::Vector3d(1.0, -2.0, 0.5).normalized()).toRotationMatrix();
    INFO(element);
    check_uniform(m, rotated(m, R, {0.3, 0.2, -1.0}), 2 * std::sin(0.2));
  }
}

TEST_CASE("a uniform stretch has |grad u| = its largest strain, and an axisymmetric radial shift c its hoop c / r",
          "[elasticity]") {
  for (bool triangles : {false, true}) {
    INFO((triangles ? "T3" : "Q4"));
    const Mesh plane = test::distorted_patch(triangles, false);
    Eigen::VectorXd u(plane.num_dofs());
    for (int n = 0; n < plane.num_nodes(); ++n)
      u[plane.dof(n, 0)] = 0.02 * plane.nodes[n].x(), u[plane.dof(n, 1)] = -0.07 * plane.nodes[n].y();
    check_uniform(plane, u, 0.07);
    // u_r = c, u_z = 0: grad u is c / r in the hoop place only; the cells' centres (the mean
    // of a Q4's corners, a T3's centroid) give the largest, c / (their smallest r).
    const Mesh ring = test::distorted_patch(triangles, true);
    const double c = 0.05;
    u.setZero();
    double r_min = 1e300;
    for (int n = 0; n < ring.num_nodes(); ++n) u[ring.dof(n, 0)] = c;
    for (const std::vector<int>& cell : ring.cells) {
      double r = 0;
      for (int n : cell) r += ring.nodes[n].x() / double(cell.size());
      r_min = std::min(r_min, r);
    }
    const DeformationExcess e = SmallStrainCheck(ring)(u, 0.0);
    CHECK(e.largest == Approx(c / r_min).epsilon(1e-12));
    CHECK(e.fraction == Approx(1.0).epsilon(1e-12));
  }
}

TEST_CASE("the share beyond the limit is by volume and per body: a strip bent by u_y = k x^2 / 2", "[elasticity]") {
  // Cells of 1 mm height over x = 0, 1, 2, 3, 3.2, 4: bodies "left" (three Q4) and "right"
  // ([3, 3.2] as two T3, [3.2, 4] a Q4). du_y/dx = k x is exact at a Q4's centre (the average
  // slope of a quadratic) and on the T3 (their nodes at x = 3 and 3.2: k 3.1), so with k = 0.1
  // and a limit of 0.33 only [3.2, 4] (0.36) is beyond: 0.8 of the right body's volume (a
  // third of its cells, a fifth of the strip's volume).
  Mesh m;
  const double xs[] = {0, 1, 2, 3, 3.2, 4};
  for (double y : {0.0, 1.0})
    for (double x : xs) m.nodes.emplace_back(x, y, 0.0);
  for (int i : {0, 1, 2}) m.cells.push_back({i, i + 1, i + 7, i + 6});
  m.cells.push_back({3, 4, 10});
  m.cells.push_back({3, 10, 9});
  m.cells.push_back({4, 5, 11, 10});
  m.cell_body = {0, 0, 0, 1, 1, 1};
  m.body_names = {"left", "right"};
  const double k = 0.1;
  Eigen::VectorXd u = Eigen::VectorXd::Zero(m.num_dofs());
  for (int n = 0; n < m.num_nodes(); ++n) u[m.dof(n, 1)] = k * m.nodes[n].x() * m.nodes[n].x() / 2;
  const SmallStrainCheck check(m);
  const DeformationExcess e = check(u, 0.33);
  CHECK(e.fraction == Approx(0.8).epsilon(1e-12));
  CHECK(e.body == 1);
  CHECK(e.largest == Approx(k * 3.6).epsilon(1e-12));
  CHECK(e.cell == 5);
  // A limit the left body's last cell (2.5 k) passes too: the right body is wholly beyond.
  const DeformationExcess lower = check(u, 0.24);
  CHECK(lower.fraction == Approx(1.0).epsilon(1e-12));
  CHECK(lower.body == 1);
  // At 0.6 k the left body's cells [1, 2] and [2, 3] are beyond, two thirds of it, the right
  // body wholly: the larger share is the right body's.
  const DeformationExcess both = check(u, 0.06);
  CHECK(both.fraction == Approx(1.0).epsilon(1e-12));
  CHECK(both.body == 1);
}

TEST_CASE("the note's body, largest gradient and cell are those of the body with the largest share", "[elasticity]") {
  // Unit squares with nodes of their own, each sheared uniformly (u_y = g x): body "stiff"
  // has ten cells, one of them at g = 0.9 (a point load's cell); body "soft" has two at g =
  // 0.2 and 0.3. Beyond 0.15: a tenth of "stiff", all of "soft": "soft", at most 0.3, its
  // second cell (not the 0.9 of the other body).
  Mesh m;
  const std::vector<double> shear = {0, 0, 0.9, 0, 0, 0, 0, 0, 0, 0, 0.2, 0.3};
  Eigen::VectorXd u = Eigen::VectorXd::Zero(2 * 4 * static_cast<Eigen::Index>(shear.size()));
  for (std::size_t c = 0; c < shear.size(); ++c) {
    const int first = m.num_nodes();
    for (const auto& xy : {std::pair{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}}) {
      m.nodes.emplace_back(2.0 * c + xy.first, xy.second, 0.0);
      u[2 * (m.num_nodes() - 1) + 1] = shear[c] * m.nodes.back().x();
    }
    m.cells.push_back({first, first + 1, first + 2, first + 3});
    m.cell_body.push_back(c < 10 ? 0 : 1);
  }
  m.body_names = {"stiff", "soft"};
  const DeformationExcess e = SmallStrainCheck(m)(u, 0.15);
  CHECK(e.body == 1);
  CHECK(e.fraction == Approx(1.0).epsilon(1e-12));
  CHECK(e.largest == Approx(0.3).epsilon(1e-12));
  CHECK(e.cell == 11);
}

TEST_CASE("a body of H8 and T4 cells weighs each by its volume: u_y = k x^2 / 2 beyond the limit in the T4 half only",
          "[elasticity]") {
  // Two unit cubes along x: [0, 1] an H8 (slope k/2 at its centre), [1, 2] as the six T4 of
  // Kuhn's split (their nodes at x = 1 and 2: slope 3k/2 exactly). Beyond k: the T4, half of
  // the body's volume (six of its seven cells).
  Mesh m = make_box(test::box(2.0, 1.0, 1.0, 2, 1, 1));
  const std::vector<int> hexahedron = m.cells[0].front() == 0 ? m.cells[0] : m.cells[1];
  const Mesh split = kuhn_tetrahedra(m);
  m.cells = {hexahedron};
  for (const std::vector<int>& t : split.cells)
    if (std::all_of(t.begin(), t.end(), [&](int n) { return m.nodes[n].x() >= 1.0; })) m.cells.push_back(t);
  REQUIRE(m.cells.size() == 7);
  m.cell_body.assign(7, 0);
  const double k = 0.2;
  Eigen::VectorXd u = Eigen::VectorXd::Zero(m.num_dofs());
  for (int n = 0; n < m.num_nodes(); ++n) u[m.dof(n, 1)] = k * m.nodes[n].x() * m.nodes[n].x() / 2;
  const DeformationExcess e = SmallStrainCheck(m)(u, k);
  CHECK(e.fraction == Approx(0.5).epsilon(1e-12));
  CHECK(e.largest == Approx(1.5 * k).epsilon(1e-12));
}

TEST_CASE("an axisymmetric body's share is by ring volume: a radial shift c beyond the limit near the axis only",
          "[elasticity]") {
  // Q4 rings 1 < r < 2, 2 < r < 3, 3 < r < 4 of height 1 (ring volumes 2 pi r_c, r_c = 1.5,
  // 2.5, 3.5: exact at the centre for a rectangle); u_r = c gives the hoop gradient c / r_c,
  // beyond c / 2 in the first ring only: 1.5 / 7.5 of the volume (a third of the cells).
  Mesh m;
  m.axisymmetric = true;
  for (double z : {0.0, 1.0})
    for (double r : {1.0, 2.0, 3.0, 4.0}) m.nodes.emplace_back(r, z, 0.0);
  for (int i : {0, 1, 2}) m.cells.push_back({i, i + 1, i + 5, i + 4});
  m.cell_body.assign(3, 0);
  m.body_names = {"rings"};
  const double c = 0.3;
  Eigen::VectorXd u = Eigen::VectorXd::Zero(m.num_dofs());
  for (int n = 0; n < m.num_nodes(); ++n) u[m.dof(n, 0)] = c;
  const DeformationExcess e = SmallStrainCheck(m)(u, c / 2);
  CHECK(e.fraction == Approx(1.5 / 7.5).epsilon(1e-12));
  CHECK(e.largest == Approx(c / 1.5).epsilon(1e-12));
}

TEST_CASE("the share beyond the limit is by volume across kinds of cells: a Q4 beside a T3 and an H8 beside a T4",
          "[elasticity]") {
  // A unit square (cube) and a triangle (tetrahedron) of area 1/2 (volume 1/6) sharing a side;
  // the triangle's free corner moves along x by 0.2: grad u = 0.2 in it, 0 in the square.
  for (int dim : {2, 3}) {
    Mesh m;
    m.dim = dim;
    const int corners = dim == 2 ? 4 : 8;
    for (int n = 0; n < corners; ++n) m.nodes.emplace_back(double(n == 1 || n == 2 || n == 5 || n == 6), double(n % 4 >= 2), double(n >= 4));
    m.cells.push_back({0, 1, 2, 3});
    if (dim == 3) m.cells.back().insert(m.cells.back().end(), {4, 5, 6, 7});
    m.nodes.emplace_back(2.0, 0.0, 0.0);
    m.cells.push_back(dim == 2 ? std::vector<int>{1, corners, 2} : std::vector<int>{1, corners, 2, 5});
    m.cell_body.assign(2, 0);
    m.body_names = {"pair"};
    Eigen::VectorXd u = Eigen::VectorXd::Zero(m.num_dofs());
    u[m.dof(corners, 0)] = 0.2;
    const DeformationExcess e = SmallStrainCheck(m)(u, 0.1);
    INFO(dim << "D");
    CHECK(e.largest == Approx(0.2).epsilon(1e-12));
    CHECK(e.cell == 1);
    CHECK(e.fraction == Approx(dim == 2 ? 0.5 / 1.5 : (1.0 / 6) / (1 + 1.0 / 6)).epsilon(1e-12));
  }
}

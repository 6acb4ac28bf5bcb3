// Mesh::bodies_holding: which bodies hold a point, on one cell of each kind (T3, Q4, T4, H8)
// against the cell's own shape, and on two cells of two bodies that share a face.
#include "rccm/fem/mesh.hpp"

#include <catch2/catch.hpp>

using namespace rccm;

namespace {

/// A map that turns and stretches the reference cells off the axes, so that no test point
/// lies on a coordinate plane by accident (2D: its upper-left block).
Eigen::Matrix3d distortion(int dim) {
  Eigen::Matrix3d A;
  A << 2.0, 0.3, 0.1, -0.4, 1.5, 0.2, 0.1, -0.2, 1.2;
  if (dim == 2) A.row(2).setZero(), A.col(2).setZero();
  return A;
}

/// One cell of `corners` mapped by distortion(dim), a body of its own ("cell").
Mesh one_cell(int dim, const std::vector<Eigen::Vector3d>& corners) {
  Mesh m;
  m.dim = dim;
  for (const Eigen::Vector3d& x : corners) m.nodes.push_back(distortion(dim) * x);
  std::vector<int> cell(corners.size());
  for (std::size_t k = 0; k < cell.size(); ++k) cell[k] = int(k);
  m.cells = {cell};
  m.cell_body = {0};
  m.body_names = {"cell"};
  return m;
}

}  // namespace

TEST_CASE("the bodies holding a point: inside a cell of each kind, not outside it, its faces included", "[mesh]") {
  using V = Eigen::Vector3d;
  struct Kind {
    const char* name;
    int dim;
    std::vector<V> corners;
    V inside, outside, on_face;  // in the reference cell
  };
  const std::vector<Kind> kinds = {
      {"T3", 2, {V(0, 0, 0), V(1, 0, 0), V(0, 1, 0)}, V(0.2, 0.3, 0), V(0.6, 0.5, 0), V(0.5, 0.5, 0)},
      {"Q4", 2, {V(0, 0, 0), V(1, 0, 0), V(1, 1, 0), V(0, 1, 0)}, V(0.9, 0.1, 0), V(1.05, 0.5, 0), V(1, 0.3, 0)},
      {"T4", 3, {V(0, 0, 0), V(1, 0, 0), V(0, 1, 0), V(0, 0, 1)}, V(0.1, 0.2, 0.3), V(0.4, 0.4, 0.3), V(0.3, 0.3, 0.4)},
      {"H8", 3, {V(0, 0, 0), V(1, 0, 0), V(1, 1, 0), V(0, 1, 0), V(0, 0, 1), V(1, 0, 1), V(1, 1, 1), V(0, 1, 1)},
       V(0.9, 0.1, 0.8), V(0.5, 1.02, 0.5), V(0.2, 0.7, 1.0)}};
  for (const Kind& k : kinds) {
    INFO(k.name);
    const Mesh m = one_cell(k.dim, k.corners);
    const Eigen::Matrix3d T = distortion(k.dim);
    CHECK(m.bodies_holding(T * k.inside) == std::vector<int>{0});
    CHECK(m.bodies_holding(T * k.on_face) == std::vector<int>{0});
    CHECK(m.bodies_holding(T * k.outside).empty());
    // every corner of the cell is in it (on its boundary)
    for (const V& c : k.corners) CHECK(m.bodies_holding(T * c) == std::vector<int>{0});
  }
}

TEST_CASE("a point on the face two bodies share is held by both, one beside it by its own", "[mesh]") {
  // Two unit squares stacked, each a body with its own nodes along y = 1.
  Mesh m;
  m.nodes = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
  m.cells = {{0, 1, 2, 3}, {4, 5, 6, 7}};
  m.cell_body = {0, 1};
  m.body_names = {"lower", "upper"};
  CHECK(m.bodies_holding({0.5, 1.0, 0}) == std::vector<int>{0, 1});
  CHECK(m.bodies_holding({0.5, 0.99, 0}) == std::vector<int>{0});
  CHECK(m.bodies_holding({0.5, 1.01, 0}) == std::vector<int>{1});
  CHECK(m.bodies_holding({1.5, 1.0, 0}).empty());
}

TEST_CASE("a cell whose split has a flat simplex holds only its own points", "[mesh]") {
  // A Q4 with three corners in a line (0, 1, 2): its first triangle is flat, and a flat
  // triangle's barycentric coordinates would claim points far off the cell.
  const Mesh m = one_cell(2, {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}});
  const Eigen::Matrix3d T = distortion(2);
  CHECK(m.bodies_holding(T * Eigen::Vector3d(0.5, 5, 0)).empty());
  CHECK(m.bodies_holding(T * Eigen::Vector3d(0.5, 0.25, 0)) == std::vector<int>{0});
}

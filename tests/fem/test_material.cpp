// Materials and the element stiffness (fem/material, fem/elasticity): the orthotropic law
// with isotropic constants is the isotropic one at any angle, turning the material axes
// turns the law, the out-of-plane components follow the hypothesis, and a distorted patch
// reproduces uniform strain states exactly in plane and axisymmetric form (with the 2 pi r
// weights checked by the strain energy and the tributary measures).
#include "helpers.hpp"
#include "rccm/fem/elasticity.hpp"
#include "rccm/fem/material.hpp"
#include "rccm/fem/mesh.hpp"

#include <catch2/catch.hpp>

#include <Eigen/Dense>

#include <array>
#include <cmath>

using namespace rccm;

namespace {

MaterialParams isotropic(double E, double nu, Hypothesis h) {
  MaterialParams p;
  p.E = E, p.nu = nu, p.hypothesis = h;
  return p;
}

MaterialParams orthotropic(double E1, double E2, double E3, double nu12, double nu13, double nu23, double G12,
                           double angle, Hypothesis h) {
  MaterialParams p;
  p.orthotropic = true;
  p.E1 = E1, p.E2 = E2, p.E3 = E3, p.nu12 = nu12, p.nu13 = nu13, p.nu23 = nu23, p.G12 = G12, p.angle = angle;
  p.hypothesis = h;
  return p;
}

/// A plane strain (xx, yy, gamma_xy) seen from axes turned by `angle` degrees.
Eigen::Vector3d strain_in_axes(const Eigen::Vector3d& e, double angle) {
  const double c = std::cos(angle * M_PI / 180), s = std::sin(angle * M_PI / 180);
  return {c * c * e[0] + s * s * e[1] + c * s * e[2], s * s * e[0] + c * c * e[1] - c * s * e[2],
          -2 * c * s * e[0] + 2 * c * s * e[1] + (c * c - s * s) * e[2]};
}

}  // namespace

TEST_CASE("orthotropic constants of an isotropic material give the isotropic law at any angle", "[material]") {
  for (Hypothesis h : {Hypothesis::PlaneStrain, Hypothesis::PlaneStress, Hypothesis::Axisymmetric})
    for (double angle : {0.0, 30.0, 90.0, 143.0}) {
      const double E = 7e4, nu = 0.3;
      const Material iso(isotropic(E, nu, h)), ortho(orthotropic(E, E, E, nu, nu, nu, E / (2 * (1 + nu)), angle, h));
      INFO("hypothesis " << int(h) << " angle " << angle);
      CHECK((iso.D() - ortho.D()).cwiseAbs().maxCoeff() <= 1e-11 * iso.D().cwiseAbs().maxCoeff());
    }
  // The closed forms: plane strain D_11 = E (1 - nu) / ((1 + nu)(1 - 2 nu)), plane stress E / (1 - nu^2).
  CHECK(Material(isotropic(100, 0.25, Hypothesis::PlaneStrain)).D()(0, 0) == Approx(100 * 0.75 / (1.25 * 0.5)));
  CHECK(Material(isotropic(100, 0.25, Hypothesis::PlaneStress)).D()(0, 0) == Approx(100 / (1 - 0.0625)));
  CHECK(Material(isotropic(100, 0.25, Hypothesis::PlaneStress)).D()(2, 2) == Approx(100 / 2.5));
}

TEST_CASE("turning the material axes turns the law: strain energy and the 90-degree swap", "[material]") {
  const double E1 = 1.2e5, E2 = 1e4, E3 = 9e3, nu12 = 0.3, nu13 = 0.28, nu23 = 0.45, G12 = 5e3;
  for (Hypothesis h : {Hypothesis::PlaneStrain, Hypothesis::PlaneStress}) {
    const Material axes(orthotropic(E1, E2, E3, nu12, nu13, nu23, G12, 0, h));
    for (double angle : {25.0, 90.0, 200.0}) {
      const Material turned(orthotropic(E1, E2, E3, nu12, nu13, nu23, G12, angle, h));
      const Eigen::Vector3d e(1e-3, -4e-4, 7e-4), e_axes = strain_in_axes(e, angle);
      INFO("hypothesis " << int(h) << " angle " << angle);
      // The energy density of a strain is that of the strain seen in the material axes.
      const double w = e.dot(turned.D().topLeftCorner<3, 3>() * e), w_axes = e_axes.dot(axes.D().topLeftCorner<3, 3>() * e_axes);
      CHECK(w == Approx(w_axes).epsilon(1e-12));
    }
    // At 90 degrees axis 1 lies along y: the law of the swapped constants (nu21 = nu12 E2 / E1).
    const Material swapped(orthotropic(E2, E1, E3, nu12 * E2 / E1, nu23, nu13, G12, 0, h));
    const Material at90(orthotropic(E1, E2, E3, nu12, nu13, nu23, G12, 90, h));
    CHECK((swapped.D() - at90.D()).cwiseAbs().maxCoeff() <= 1e-10 * swapped.D().cwiseAbs().maxCoeff());
  }
  // Uniaxial stress along axis 1 in plane stress: strain sigma / E1 along 1, -nu12 sigma / E1 along 2.
  const Material ps(orthotropic(E1, E2, E3, nu12, nu13, nu23, G12, 0, Hypothesis::PlaneStress));
  const Eigen::Vector3d eps = ps.D().topLeftCorner<3, 3>().inverse() * Eigen::Vector3d(100, 0, 0);
  CHECK(eps[0] == Approx(100 / E1));
  CHECK(eps[1] == Approx(-nu12 * 100 / E1));
}

TEST_CASE("the out-of-plane components follow the hypothesis", "[material]") {
  const double E = 1000, nu = 0.3;
  Voigt eps(1e-3, 2e-3, 5e-4, 0), sigma;
  Material(isotropic(E, nu, Hypothesis::PlaneStrain)).complete(eps, sigma);
  CHECK(eps[3] == 0);
  CHECK(sigma[3] == Approx(nu * (sigma[0] + sigma[1])));  // plane strain: sigma_zz = nu (sigma_xx + sigma_yy)
  eps << 1e-3, 2e-3, 5e-4, 0;
  Material(isotropic(E, nu, Hypothesis::PlaneStress)).complete(eps, sigma);
  CHECK(sigma[3] == 0);
  CHECK(eps[3] == Approx(-nu / (1 - nu) * (eps[0] + eps[1])));  // plane stress: eps_zz from sigma_zz = 0
  eps << 1e-3, 2e-3, 5e-4, 3e-4;
  Material(isotropic(E, nu, Hypothesis::Axisymmetric)).complete(eps, sigma);
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  CHECK(sigma[3] == Approx(lambda * (eps[0] + eps[1] + eps[3]) + 2 * mu * eps[3]));  // the hoop stress
}

TEST_CASE("orthotropic out-of-plane coupling: nu13 couples axis 1 to 3, nu23 axis 2 to 3", "[material]") {
  // Material axes along x, y: eps_33 = -nu13 / E1 sigma_11 - nu23 / E2 sigma_22 + sigma_33 / E3.
  const double E1 = 140e3, E2 = 10e3, E3 = 9e3, nu12 = 0.3, nu13 = 0.25, nu23 = 0.45, G12 = 5e3;
  Voigt eps(1e-3, 2e-3, 5e-4, 0), sigma;
  Material(orthotropic(E1, E2, E3, nu12, nu13, nu23, G12, 0, Hypothesis::PlaneStrain)).complete(eps, sigma);
  CHECK(sigma[3] == Approx(E3 * (nu13 * sigma[0] / E1 + nu23 * sigma[1] / E2)));  // eps_33 = 0
  eps << 1e-3, 2e-3, 5e-4, 0;
  Material(orthotropic(E1, E2, E3, nu12, nu13, nu23, G12, 0, Hypothesis::PlaneStress)).complete(eps, sigma);
  CHECK(sigma[3] == 0);
  CHECK(eps[3] == Approx(-nu13 * sigma[0] / E1 - nu23 * sigma[1] / E2));  // sigma_33 = 0
}

TEST_CASE("3D orthotropic law: uniaxial stress along the turned axes gives the engineering constants, the "
          "shears G12, G13, G23, the plane block is the plane-strain law, for axis 3 along z, y, x or oblique",
          "[material]") {
  const double E1 = 1.4e5, E2 = 1e4, E3 = 9e3, nu12 = 0.3, nu13 = 0.25, nu23 = 0.45, G12 = 5e3, G13 = 4.5e3, G23 = 3.4e3;
  // axis3 and the reference axes (1, 2) at angle 0 (README "3D": x projected on the plane
  // normal to axis 3, y when axis 3 is along x; axis 2 = axis 3 x axis 1).
  const auto projected = [](const Eigen::Vector3d& reference, const Eigen::Vector3d& n) {
    const Eigen::Vector3d r1 = (reference - reference.dot(n) * n).normalized();
    return std::array<Eigen::Vector3d, 3>{n, r1, n.cross(r1)};
  };
  const double deg = M_PI / 180;
  const std::array<std::array<Eigen::Vector3d, 3>, 6> frames{{
      {{{0, 0, 1}, {1, 0, 0}, {0, 1, 0}}},  // the default: the plane axes turned about z
      {{{0, 1, 0}, {1, 0, 0}, {0, 0, -1}}},  // a plate in x-z (the corner peel's)
      {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}},
      projected(Eigen::Vector3d::UnitX(), Eigen::Vector3d(1, 2, 3).normalized()),
      // 30 degrees from x (|n_x| = 0.87 < 0.9): x projected; 20 degrees (0.94): y projected
      // (out of the x-y plane, where the two projections are not parallel).
      projected(Eigen::Vector3d::UnitX(),
                Eigen::Vector3d(std::cos(30 * deg), std::sin(30 * deg) * std::cos(45 * deg), std::sin(30 * deg) * std::sin(45 * deg))),
      projected(Eigen::Vector3d::UnitY(), Eigen::Vector3d(std::cos(20 * deg), 0, std::sin(20 * deg))),
  }};
  for (const auto& frame : frames)
    for (double angle : {0.0, 30.0, 117.0}) {
      MaterialParams p = orthotropic(E1, E2, E3, nu12, nu13, nu23, G12, angle, Hypothesis::PlaneStrain);
      p.G13 = G13, p.G23 = G23;
      p.axis3 = {frame[0].x(), frame[0].y(), frame[0].z()};
      const Material m(p);
      const Eigen::Matrix<double, 6, 6> S = m.D3().inverse();
      CHECK((m.D3() - m.D3().transpose()).cwiseAbs().maxCoeff() <= 1e-10 * m.D3().cwiseAbs().maxCoeff());
      CHECK(m.D3().selfadjointView<Eigen::Lower>().eigenvalues().minCoeff() > 0);
      // The material axes in the global frame: 1 = c r1 + s r2, 2 = -s r1 + c r2, 3 = axis3.
      const double a = angle * M_PI / 180;
      const Eigen::Vector3d axis[3] = {std::cos(a) * frame[1] + std::sin(a) * frame[2],
                                       -std::sin(a) * frame[1] + std::cos(a) * frame[2], frame[0]};
      const auto voigt_stress = [](const Eigen::Matrix3d& t) {
        Voigt3 v;
        v << t(0, 0), t(1, 1), t(2, 2), t(1, 2), t(0, 2), t(0, 1);
        return v;
      };
      const auto strain_tensor = [](const Voigt3& e) {
        Eigen::Matrix3d t;
        t << e[0], e[5] / 2, e[4] / 2, e[5] / 2, e[1], e[3] / 2, e[4] / 2, e[3] / 2, e[2];
        return t;
      };
      const double E[3] = {E1, E2, E3};
      const double nu[3][3] = {{0, nu12, nu13}, {nu12 * E2 / E1, 0, nu23}, {nu13 * E3 / E1, nu23 * E3 / E2, 0}};  // nu_ij
      for (int i = 0; i < 3; ++i) {  // a uniaxial stress of 100 MPa along axis i
        const Eigen::Matrix3d eps = strain_tensor(S * voigt_stress(100 * axis[i] * axis[i].transpose()));
        INFO("axis3 " << frame[0].transpose() << ", angle " << angle << ", stress along axis " << i + 1);
        CHECK(axis[i].dot(eps * axis[i]) == Approx(100 / E[i]).epsilon(1e-10));
        for (int j = 0; j < 3; ++j)
          if (j != i) {
            CHECK(axis[j].dot(eps * axis[j]) == Approx(-nu[i][j] * 100 / E[i]).epsilon(1e-10));
            CHECK(std::abs(axis[i].dot(eps * axis[j])) <= 1e-12 * 100 / E[i]);  // no shear
          }
      }
      const double G[3][3] = {{0, G12, G13}, {G12, 0, G23}, {G13, G23, 0}};
      for (int i = 0; i < 3; ++i)  // a pure shear of 10 MPa in the axes' plane i-j: gamma = tau / G_ij
        for (int j = i + 1; j < 3; ++j) {
          const Eigen::Matrix3d tau = 10 * (axis[i] * axis[j].transpose() + axis[j] * axis[i].transpose());
          const Eigen::Matrix3d eps = strain_tensor(S * voigt_stress(tau));
          CHECK(2 * axis[i].dot(eps * axis[j]) == Approx(10 / G[i][j]).epsilon(1e-10));
        }
      // The plane-strain law is the 3D law's block of xx, yy, xy, zz.
      const int plane[4] = {0, 1, 5, 2};
      for (int A = 0; A < 4; ++A)
        for (int B = 0; B < 4; ++B) CHECK(m.D()(A, B) == Approx(m.D3()(plane[A], plane[B])).epsilon(1e-12).margin(1e-9));
    }
}

TEST_CASE("patch test: a distorted patch carries uniform strain exactly, plane and axisymmetric", "[material]") {
  for (bool triangles : {false, true})
    for (bool axisymmetric : {false, true}) {
      INFO((triangles ? "T3" : "Q4") << (axisymmetric ? " axisymmetric" : " plane"));
      const Mesh m = test::distorted_patch(triangles, axisymmetric);
      const MaterialParams p = axisymmetric ? isotropic(1000, 0.3, Hypothesis::Axisymmetric)
                                            : orthotropic(1.2e5, 1e4, 9e3, 0.3, 0.28, 0.45, 5e3, 35, Hypothesis::PlaneStrain);
      const std::vector<Material> materials{Material(p)};
      const SparseMatrix K = assemble_stiffness(m, materials);
      // u = (c r, d z) (axisymmetric: eps_rr = eps_thth = c, in equilibrium for an isotropic
      // body); plane: any linear field, here with shear.
      const double c = 1e-3, d = -4e-4, g = axisymmetric ? 0.0 : 6e-4;
      Eigen::VectorXd u(m.num_dofs());
      for (int n = 0; n < m.num_nodes(); ++n) {
        u[m.dof(n, 0)] = c * m.nodes[n].x() + g * m.nodes[n].y();
        u[m.dof(n, 1)] = d * m.nodes[n].y();
      }
      const Eigen::VectorXd f = K * u;
      CHECK(f.segment<2>(m.dof(4, 0)).norm() <= 1e-12 * f.cwiseAbs().maxCoeff());  // the inner node is in equilibrium
      // Uniform strain and stress in every cell, and the strain energy sigma:eps V / 2 with V
      // the patch's area, or its volume 2 pi int r dA = 2 pi (centroid r = 2) (area 4).
      const CellFields fields = cell_fields(m, materials, u);
      const Voigt eps0 = fields.strain.col(0), sigma0 = fields.stress.col(0);
      for (Eigen::Index k = 0; k < fields.strain.cols(); ++k)
        CHECK((fields.strain.col(k) - eps0).norm() <= 1e-12 * eps0.norm());
      CHECK(eps0[0] == Approx(c));
      CHECK(eps0[1] == Approx(d));
      CHECK(eps0[2] == Approx(g).margin(1e-15));
      if (axisymmetric) CHECK(eps0[3] == Approx(c));
      const double volume = axisymmetric ? 2 * M_PI * 2 * 4 : 4;
      CHECK(0.5 * u.dot(K * u) == Approx(0.5 * sigma0.dot(eps0) * volume).epsilon(1e-12));
    }
}

TEST_CASE("tributary measures are lengths in the plane and ring areas on an axisymmetric mesh", "[material]") {
  for (bool axisymmetric : {false, true}) {
    const Mesh m = test::distorted_patch(false, axisymmetric);
    const std::vector<int> bottom = {0, 1, 2}, right = {2, 5, 8};
    double a_bottom = 0, a_right = 0, l_bottom = 0;
    for (double a : m.tributary_measures(bottom, m.facets_within(bottom))) a_bottom += a;
    for (double a : m.tributary_measures(right, m.facets_within(right))) a_right += a;
    for (double l : m.tributary_lengths(bottom, m.facets_within(bottom))) l_bottom += l;
    CHECK(l_bottom == Approx(2.0));
    // The annulus 1 < r < 3 (pi (9 - 1)) and the cylinder r = 3 of height 2 (2 pi 3 2).
    CHECK(a_bottom == Approx(axisymmetric ? M_PI * 8 : 2.0));
    CHECK(a_right == Approx(axisymmetric ? 2 * M_PI * 3 * 2 : 2.0));
  }
}

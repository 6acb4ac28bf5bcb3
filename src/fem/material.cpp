#include "rccm/fem/material.hpp"

#include "rccm/base/errors.hpp"

#include <Eigen/Dense>

#include <cmath>

namespace rccm {

namespace {

/// The index pairs of the 3D Voigt order 11, 22, 33, 23, 13, 12.
constexpr int pair_of[6][2] = {{0, 0}, {1, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};

/// C_ijkl of a stiffness in 3D Voigt form (engineering shear strains).
double tensor(const Eigen::Matrix<double, 6, 6>& C, int i, int j, int k, int l) {
  const auto voigt = [](int a, int b) {
    for (int v = 0; v < 6; ++v)
      if ((pair_of[v][0] == a && pair_of[v][1] == b) || (pair_of[v][0] == b && pair_of[v][1] == a)) return v;
    return -1;
  };
  return C(voigt(i, j), voigt(k, l));
}

/// An isotropic stiffness in (xx, yy, xy, zz), in closed form.
Eigen::Matrix4d isotropic_stiffness(double E, double nu) {
  Eigen::Matrix4d C;
  C << 1 - nu, nu, 0, nu,          //
      nu, 1 - nu, 0, nu,           //
      0, 0, (1 - 2 * nu) / 2, 0,   //
      nu, nu, 0, 1 - nu;
  return E / ((1 + nu) * (1 - 2 * nu)) * C;
}

/// An orthotropic stiffness in the global Voigt order (xx, yy, zz, yz, xz, xy), its material
/// axes the columns of R (material_axes): C'_ijkl = R_ip R_jq R_kr R_ls C_pqrs (engineering
/// shear strains: no factors).
Eigen::Matrix<double, 6, 6> rotated_stiffness(const MaterialParams& p) {
  const Eigen::Matrix<double, 6, 6> C = compliance_in_material_axes(p).inverse();
  const Eigen::Matrix3d R = material_axes(p);
  Eigen::Matrix<double, 6, 6> turned;
  for (int A = 0; A < 6; ++A)
    for (int B = 0; B < 6; ++B) {
      const int i = pair_of[A][0], j = pair_of[A][1], k = pair_of[B][0], l = pair_of[B][1];
      double c = 0;
      for (int P = 0; P < 3; ++P)
        for (int Q = 0; Q < 3; ++Q)
          for (int r = 0; r < 3; ++r)
            for (int s = 0; s < 3; ++s) c += R(i, P) * R(j, Q) * R(k, r) * R(l, s) * tensor(C, P, Q, r, s);
      turned(A, B) = c;
    }
  return turned;
}

/// The plane block (xx, yy, xy, zz) of a 3D stiffness.
Eigen::Matrix4d plane_block(const Eigen::Matrix<double, 6, 6>& C) {
  const int plane[4] = {0, 1, 5, 2};  // xx, yy, xy, zz in the 3D Voigt order
  Eigen::Matrix4d C4;
  for (int A = 0; A < 4; ++A)
    for (int B = 0; B < 4; ++B) C4(A, B) = C(plane[A], plane[B]);
  return C4;
}

}  // namespace

Eigen::Matrix3d material_axes(const MaterialParams& p) {
  const Eigen::Vector3d n(p.axis3[0], p.axis3[1], p.axis3[2]);
  RCCM_VERIFY(std::abs(n.norm() - 1) < 1e-12, "material_axes(): axis3 must be a unit vector (the config reader makes it one)");
  // Axis 1 at angle 0: x projected on the plane normal to axis 3 (y when axis 3 is along x).
  const Eigen::Vector3d x = std::abs(n.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d e1 = (x - x.dot(n) * n).normalized(), e2 = n.cross(e1);
  const double a = p.angle * M_PI / 180.0;
  Eigen::Matrix3d R;
  R.col(0) = std::cos(a) * e1 + std::sin(a) * e2;
  R.col(1) = -std::sin(a) * e1 + std::cos(a) * e2;
  R.col(2) = n;
  return R;
}

Eigen::Matrix<double, 6, 6> compliance_in_material_axes(const MaterialParams& p) {
  double E1 = p.E, E2 = p.E, E3 = p.E, nu12 = p.nu, nu13 = p.nu, nu23 = p.nu, G12 = p.E / (2 * (1 + p.nu));
  if (p.orthotropic) E1 = p.E1, E2 = p.E2, E3 = p.E3, nu12 = p.nu12, nu13 = p.nu13, nu23 = p.nu23, G12 = p.G12;
  Eigen::Matrix<double, 6, 6> S = Eigen::Matrix<double, 6, 6>::Zero();
  S(0, 0) = 1 / E1, S(1, 1) = 1 / E2, S(2, 2) = 1 / E3;
  S(0, 1) = S(1, 0) = -nu12 / E1;
  S(0, 2) = S(2, 0) = -nu13 / E1;
  S(1, 2) = S(2, 1) = -nu23 / E2;
  // G23, G13: decoupled from the plane (any positive value there); 3D: given, or isotropic's.
  S(3, 3) = 1 / (p.orthotropic && p.G23 > 0 ? p.G23 : G12);
  S(4, 4) = 1 / (p.orthotropic && p.G13 > 0 ? p.G13 : G12);
  S(5, 5) = 1 / G12;
  return S;
}

Material::Material(const MaterialParams& p) : hypothesis_(p.hypothesis) {
  if (!p.orthotropic) {  // Lame: sigma = lambda tr(eps) I + 2 G eps (G on the engineering shears)
    const double G = p.E / (2 * (1 + p.nu)), lambda = p.E * p.nu / ((1 + p.nu) * (1 - 2 * p.nu));
    D3_.topLeftCorner<3, 3>().setConstant(lambda);
    D3_.topLeftCorner<3, 3>().diagonal().array() += 2 * G;
    D3_.bottomRightCorner<3, 3>().diagonal().setConstant(G);
  } else {
    D3_ = rotated_stiffness(p);
  }
  // Isotropic in closed form: B2's explicit runs amplify a last-bit change of K to 1e-7.
  const Eigen::Matrix4d C4 = p.orthotropic ? plane_block(D3_) : isotropic_stiffness(p.E, p.nu);
  S_ = C4.inverse();
  if (hypothesis_ == Hypothesis::PlaneStress) {  // sigma_zz = 0: the in-plane block of the compliance inverted
    D_.setZero();
    D_.topLeftCorner<3, 3>() = S_.topLeftCorner<3, 3>().inverse();
  } else {
    D_ = C4;
  }
}

void Material::complete(Voigt& eps, Voigt& sigma) const {
  sigma = D_ * eps;
  if (hypothesis_ == Hypothesis::PlaneStress) eps[3] = S_.row(3) * sigma;
}

}  // namespace rccm

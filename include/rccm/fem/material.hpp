// The elasticity of one body (docs/MODEL.md s1): isotropic or orthotropic, reduced to the
// plane by the body's hypothesis. Stresses and strains in the Voigt order
// (xx, yy, xy, zz): in plane, engineering shear, and the out-of-plane component (the hoop
// component theta-theta of an axisymmetric body, with x = r and y = z).
#pragma once

#include "rccm/base/config.hpp"

#include <Eigen/Core>

namespace rccm {

using Voigt = Eigen::Vector4d;  // xx, yy, xy (engineering in a strain), zz
using Voigt3 = Eigen::Matrix<double, 6, 1>;  // 3D: xx, yy, zz, yz, xz, xy (engineering shears in a strain)

class Material {
 public:
  explicit Material(const MaterialParams& p);

  /// D with sigma = D eps: plane strain (eps_zz = 0: sigma_zz from D's last row),
  /// axisymmetric (eps_zz = u_r / r), plane stress (sigma_zz = 0: D's last row and column zero).
  const Eigen::Matrix4d& D() const { return D_; }

  /// The strain and stress of an element's strain `eps` (eps_zz the element's: 0 in a plane,
  /// u_r / r axisymmetric) with the out-of-plane components filled in.
  void complete(Voigt& eps, Voigt& sigma) const;

  Hypothesis hypothesis() const { return hypothesis_; }

  /// The 3D law, sigma = D3 eps in the Voigt order of Voigt3 (orthotropic: in its
  /// material_axes).
  const Eigen::Matrix<double, 6, 6>& D3() const { return D3_; }

 private:
  Hypothesis hypothesis_;
  Eigen::Matrix4d D_, S_;  // S_: the compliance of the (xx, yy, xy, zz) block of the 3D law
  Eigen::Matrix<double, 6, 6> D3_ = Eigen::Matrix<double, 6, 6>::Zero();
};

/// The material axes 1, 2, 3 of `p` as the columns of a rotation: axis 3 along p.axis3 (z
/// in 2D), axis 1 at p.angle from the reference axis (x projected on the plane normal to
/// axis 3; y when |axis3 . x| >= 0.9, i.e. within 25.8 degrees of the x axis), turning towards axis 2 = axis 3 x axis 1.
Eigen::Matrix3d material_axes(const MaterialParams& p);

/// The compliance of `p` in its material axes (Voigt 11, 22, 33, 23, 13, 12, engineering
/// shear), MPa^-1. The out-of-plane shears (G23, G13) decouple from the plane: a plane body
/// does not need them (G12 stands in).
Eigen::Matrix<double, 6, 6> compliance_in_material_axes(const MaterialParams& p);

}  // namespace rccm

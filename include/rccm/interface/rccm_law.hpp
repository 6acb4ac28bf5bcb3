// The RCCM interface law (Raous, Cangemi, Cocou; docs/MODEL.md s3): its parameters and every
// formula of it, once. Local vectors u are the relative displacement of a contact pair,
// tangential components first, normal last (layout.hpp); a is the pair's tributary measure.
#pragma once

#include "rccm/interface/layout.hpp"

namespace rccm {

struct RccmLaw {
  double Cn = 0, Ct = 0;  // initial normal and tangential stiffness, MPa/mm
  double w = 0;           // adhesion energy threshold, mJ/mm^2 = N/mm
  double alpha = 0;       // viscosity, N s/mm (0: the rate-independent limit)
  double mu = 0;          // Coulomb coefficient

  /// Cn u_n^2 + Ct |u_t|^2, N/mm: the opening energy density without beta.
  double opening_energy(const LocalVector& u) const;

  /// Thermodynamic force G = w - (Cn u_n^2 + Ct |u_t|^2) beta (paper eq. 17); damage grows while G < 0.
  double thermodynamic_force(double beta, const LocalVector& u) const;

  /// d beta / dt = -(1/alpha) max(0, -G) (paper eq. 31, docs/MODEL.md s6); alpha > 0.
  double beta_rate(double beta, const LocalVector& u) const;

  /// d(beta_rate) / d beta at fixed u: -(Cn u_n^2 + Ct |u_t|^2)/alpha where damage grows, else 0
  /// (the modified-Newton matrix of docs/MODEL.md s6).
  double beta_rate_derivative(double beta, const LocalVector& u) const;

  /// The rate-independent limit alpha -> 0 (docs/MODEL.md s3): min(beta_max, w / (Cn u_n^2 + Ct |u_t|^2)).
  double rate_independent_beta(double beta_max, const LocalVector& u) const;

  /// Friction coefficient of the contact part, mubar = mu (1 - beta) (paper eq. 20).
  double mubar(double beta) const;

  /// The adhesive spring at beta = 1 per local component, a (Ct, .., Cn), N/mm (docs/MODEL.md s4: D(1)).
  LocalVector spring(double a, int dim) const;

  /// Adhesive force Radh = -a beta^2 (Ct u_t, Cn u_n), N (paper eq. 19).
  LocalVector adhesive_force(double a, double beta, const LocalVector& u) const;

  /// Interface free energy per unit measure psi = 1/2 beta^2 (Cn u_n^2 + Ct |u_t|^2) - w beta, N/mm.
  double free_energy(double beta, const LocalVector& u) const;
};

}  // namespace rccm

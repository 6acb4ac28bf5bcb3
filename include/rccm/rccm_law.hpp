// The RCCM interface law at one contact node, as pure functions (MODEL.md s3, s5).
// Local vectors are (t, n) components: index 0 tangential, index 1 normal.
#pragma once

#include <Eigen/Core>

namespace rccm {

using Vec2 = Eigen::Vector2d;

/// Branch of the projection on the Coulomb cone K_mubar = {|R_t| <= mubar R_n}.
enum class Status { Separated, Stick, Slide };
const char* status_name(Status s);

/// Which branch of the projection `tau` falls in (paper eqs. 38a-c).
Status cone_branch(const Vec2& tau, double mubar);

/// Projection of tau on K_mubar (MODEL.md s5, paper eqs. 38a-c).
Vec2 project_cone(const Vec2& tau, double mubar);

/// De Saxce's modified velocity (here: increment) s = (du_t, g + mubar |du_t|) (paper eq. 33).
Vec2 modified_velocity(double du_t, double gap, double mubar);

/// Adhesive force Radh = -a beta^2 (Ct u_t, Cn u_n) of a node of tributary length a (paper eq. 19).
Vec2 adhesive_force(double a, double beta, double Ct, double Cn, const Vec2& u);

/// Thermodynamic force G = w - (Cn u_n^2 + Ct u_t^2) beta (paper eq. 17).
double thermodynamic_force(double beta, const Vec2& u, double Ct, double Cn, double w);

/// d beta / dt = -(1/alpha) max(0, -G) (paper eq. 31, MODEL.md s6); alpha > 0.
double beta_rate(double beta, const Vec2& u, double Ct, double Cn, double w, double alpha);

/// Interface free energy per unit length psi = 1/2 beta^2 (Cn u_n^2 + Ct u_t^2) - w beta.
double free_energy(double beta, const Vec2& u, double Ct, double Cn, double w);

}  // namespace rccm

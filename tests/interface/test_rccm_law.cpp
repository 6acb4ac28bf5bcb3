// The RCCM law (docs/MODEL.md s3): adhesive force, thermodynamic force, beta rate and its
// derivative (against finite differences), rate-independent limit, free energy.
#include "rccm/interface/rccm_law.hpp"

#include <catch2/catch.hpp>

#include <random>

using namespace rccm;

namespace {
LocalVector local(std::initializer_list<double> v) {
  LocalVector u(static_cast<Eigen::Index>(v.size()));
  std::copy(v.begin(), v.end(), u.data());
  return u;
}
}  // namespace

TEST_CASE("adhesive force, thermodynamic force and beta rate follow docs/MODEL.md s3", "[law]") {
  const RccmLaw law{20.0, 10.0, 1.0, 2.0, 0.3};  // Cn, Ct, w, alpha, mu
  // Radh pulls the node back to its bonded position: -a beta^2 (Ct u_t, Cn u_n).
  const LocalVector Radh = law.adhesive_force(2.0, 0.5, local({0.1, 0.3}));
  CHECK(Radh[0] == Approx(-2.0 * 0.25 * 10.0 * 0.1));
  CHECK(Radh[1] == Approx(-2.0 * 0.25 * 20.0 * 0.3));
  // 3D: both tangential components with Ct.
  const LocalVector R3 = law.adhesive_force(2.0, 0.5, local({0.1, -0.2, 0.3}));
  CHECK(R3[1] == Approx(-2.0 * 0.25 * 10.0 * -0.2));
  CHECK(R3[2] == Approx(-2.0 * 0.25 * 20.0 * 0.3));
  // Opening energy Cn u_n^2 + Ct |u_t|^2: the normal stiffness on the normal component.
  CHECK(law.opening_energy(local({1.0, 2.0})) == Approx(20.0 * 4 + 10.0 * 1));
  CHECK(law.opening_energy(local({1.0, 1.0, 2.0})) == Approx(20.0 * 4 + 10.0 * 2));
  // Below the threshold (G >= 0) no damage; above, alpha dbeta/dt = G.
  CHECK(law.beta_rate(1.0, local({0.0, 0.001})) == 0.0);
  const double G = law.thermodynamic_force(0.8, local({1.0, 2.0}));  // 1 - (80 + 10) 0.8
  CHECK(G == Approx(1 - 90 * 0.8));
  CHECK(law.beta_rate(0.8, local({1.0, 2.0})) == Approx(G / 2.0));
  CHECK(RccmLaw{1.0, 1.0, 0.7, 1.0, 0.0}.free_energy(1.0, local({0.0, 0.0})) == Approx(-0.7));
}

TEST_CASE("the law's other quantities: mubar, springs, free energy, rate-independent beta", "[law]") {
  const RccmLaw law{4.0, 3.0, 0.5, 1.0, 0.4};
  CHECK(law.mubar(1.0) == 0.0);  // no friction while fully bonded
  CHECK(law.mubar(0.0) == 0.4);
  CHECK(law.mubar(0.25) == Approx(0.3));
  const LocalVector D = law.spring(2.0, 2);
  CHECK(D[0] == 6.0);  // a Ct on the tangential component
  CHECK(D[1] == 8.0);  // a Cn on the normal one
  // psi = 1/2 beta^2 (Cn u_n^2 + Ct u_t^2) - w beta
  CHECK(law.free_energy(0.5, local({1.0, 1.0})) == Approx(0.5 * 0.25 * 7.0 - 0.25));
  // Rate-independent: beta = w / e when the opening energy exceeds w, else unchanged.
  CHECK(law.rate_independent_beta(1.0, local({0.0, 1.0})) == Approx(0.5 / 4.0));
  CHECK(law.rate_independent_beta(1.0, local({0.0, 0.1})) == 1.0);
  CHECK(law.rate_independent_beta(0.05, local({0.0, 1.0})) == 0.05);  // never grows back
}

TEST_CASE("the beta rate's derivative equals its finite difference, and G dbeta = alpha beta'^2", "[law]") {
  std::mt19937 gen(5);
  std::uniform_real_distribution<double> U(-1, 1), P(0.05, 1);
  for (int k = 0; k < 200; ++k) {
    const RccmLaw law{P(gen) * 10, P(gen) * 10, P(gen) * 0.5, P(gen) * 3, P(gen)};
    const LocalVector u = local({U(gen), U(gen)});
    const double beta = P(gen), h = 1e-7;
    const double fd = (law.beta_rate(beta + h, u) - law.beta_rate(beta - h, u)) / (2 * h);
    const double e = law.opening_energy(u);
    INFO("k " << k << " e beta " << e * beta << " w " << law.w);
    if (std::abs(e * beta - law.w) > 1e-5 * e) CHECK(law.beta_rate_derivative(beta, u) == Approx(fd).epsilon(1e-6).margin(1e-9));
    // The dissipation rate G beta' equals alpha beta'^2 >= 0 (docs/MODEL.md s3).
    const double rate = law.beta_rate(beta, u);
    CHECK(law.thermodynamic_force(beta, u) * rate == Approx(law.alpha * rate * rate).margin(1e-14));
    CHECK(law.thermodynamic_force(beta, u) * rate >= 0);
  }
}

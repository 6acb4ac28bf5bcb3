// The projection on the Coulomb cone and the local law (MODEL.md s3, s5).
#include "rccm/rccm_law.hpp"

#include <catch2/catch.hpp>

#include <random>

using namespace rccm;

namespace {
bool in_cone(const Vec2& R, double mubar, double tol = 1e-12) {
  return R[1] >= -tol && std::abs(R[0]) <= mubar * R[1] + tol;
}
}  // namespace

TEST_CASE("cone projection: each branch of eq. 38", "[law]") {
  const double mu = 0.5;
  SECTION("separated: tau in the polar cone goes to zero") {
    CHECK(cone_branch(Vec2(0.1, -1.0), mu) == Status::Separated);
    CHECK(project_cone(Vec2(0.1, -1.0), mu).norm() == 0.0);
  }
  SECTION("stick: tau inside the cone is kept") {
    const Vec2 tau(0.2, 1.0);
    CHECK(cone_branch(tau, mu) == Status::Stick);
    CHECK((project_cone(tau, mu) - tau).norm() == 0.0);
  }
  SECTION("slide: tau outside goes to the nearest point of the boundary ray") {
    const Vec2 tau(2.0, 1.0);
    CHECK(cone_branch(tau, mu) == Status::Slide);
    const Vec2 R = project_cone(tau, mu);
    CHECK(R[0] == Approx(mu * R[1]));
    // The correction tau - R is normal to the ray direction (1, ...) / |.|:
    const Vec2 ray = Vec2(mu, 1.0).normalized();
    CHECK((tau - R).dot(ray) == Approx(0.0).margin(1e-14));
    // Negative tangential side: symmetric.
    const Vec2 Rm = project_cone(Vec2(-2.0, 1.0), mu);
    CHECK(Rm[0] == Approx(-R[0]));
    CHECK(Rm[1] == Approx(R[1]));
  }
}

TEST_CASE("cone projection with mubar = 0 is the half-line R_t = 0, R_n >= 0", "[law]") {
  CHECK((project_cone(Vec2(3.0, 2.0), 0.0) - Vec2(0.0, 2.0)).norm() == 0.0);
  CHECK(project_cone(Vec2(3.0, -2.0), 0.0).norm() == 0.0);
  CHECK((project_cone(Vec2(0.0, 2.0), 0.0) - Vec2(0.0, 2.0)).norm() == 0.0);
}

TEST_CASE("cone projection is continuous across the branch boundaries", "[law]") {
  const double mu = 0.3, h = 1e-9;
  // Stick/slide boundary: |tau_t| = mu tau_n.
  const Vec2 b1(mu * 2.0, 2.0);
  CHECK((project_cone(b1 + Vec2(h, 0), mu) - project_cone(b1 - Vec2(h, 0), mu)).norm() < 10 * h);
  // Slide/separated boundary: mu |tau_t| = -tau_n.
  const Vec2 b2(2.0, -mu * 2.0);
  CHECK((project_cone(b2 + Vec2(0, h), mu) - project_cone(b2 - Vec2(0, h), mu)).norm() < 10 * h);
  CHECK(project_cone(b2 + Vec2(0, h), mu).norm() < 10 * h);
}

TEST_CASE("cone projection: idempotent, in the cone, and variational", "[law]") {
  std::mt19937 gen(42);
  std::uniform_real_distribution<double> U(-5, 5), M(0, 1.5);
  for (int k = 0; k < 2000; ++k) {
    const double mu = k % 10 == 0 ? 0.0 : M(gen);
    const Vec2 tau(U(gen), U(gen));
    const Vec2 P = project_cone(tau, mu);
    REQUIRE(in_cone(P, mu));
    REQUIRE((project_cone(P, mu) - P).norm() <= 1e-12 * (1 + P.norm()));
    // (tau - P(tau)) . (R - P(tau)) <= 0 for every R of the cone.
    const double Rn = std::abs(U(gen));
    const Vec2 R(mu * Rn * (2 * M(gen) / 1.5 - 1), Rn);
    REQUIRE((tau - P).dot(R - P) <= 1e-10);
  }
}

TEST_CASE("modified velocity, adhesive force and beta rate follow MODEL.md s3", "[law]") {
  CHECK((modified_velocity(-0.2, 0.1, 0.5) - Vec2(-0.2, 0.2)).norm() < 1e-15);
  // Radh pulls the node back to its bonded position.
  const Vec2 Radh = adhesive_force(2.0, 0.5, 10.0, 20.0, Vec2(0.1, 0.3));
  CHECK(Radh[0] == Approx(-2.0 * 0.25 * 10.0 * 0.1));
  CHECK(Radh[1] == Approx(-2.0 * 0.25 * 20.0 * 0.3));
  // Below the threshold (G >= 0) no damage; above, alpha dbeta/dt = G.
  CHECK(beta_rate(1.0, Vec2(0.0, 0.001), 1.0, 1.0, 1.0, 2.0) == 0.0);
  const double G = thermodynamic_force(0.8, Vec2(1.0, 2.0), 3.0, 4.0, 1.0);  // 1 - (16 + 3) 0.8
  CHECK(G == Approx(1 - 19 * 0.8));
  CHECK(beta_rate(0.8, Vec2(1.0, 2.0), 3.0, 4.0, 1.0, 2.0) == Approx(G / 2.0));
  CHECK(free_energy(1.0, Vec2::Zero(), 1, 1, 0.7) == Approx(-0.7));
}

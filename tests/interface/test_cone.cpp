// The projection on the Coulomb cone (docs/MODEL.md s5, paper eqs. 33-38): its branches,
// continuity, and the variational inequality that defines it, in 2D and 3D.
#include "rccm/interface/cone.hpp"

#include <catch2/catch.hpp>

#include <random>

using namespace rccm;
using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;

namespace {
template <class V>
bool in_cone(const V& R, double mubar, double tol = 1e-12) {
  return R[R.size() - 1] >= -tol && tangential_norm(R) <= mubar * R[R.size() - 1] + tol;
}
}  // namespace

TEST_CASE("modified velocity: (du_t, g + mubar |du_t|) (paper eq. 33)", "[law]") {
  CHECK((modified_velocity(Vec2(-0.2, 0.1), 0.5) - Vec2(-0.2, 0.2)).norm() < 1e-15);
  CHECK((modified_velocity(Vec3(0.3, -0.4, 0.1), 0.5) - Vec3(0.3, -0.4, 0.35)).norm() < 1e-15);
}

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

TEST_CASE("3D circular cone: in the cone, idempotent, variational on random points", "[law][3d]") {
  std::mt19937 gen(43);
  std::uniform_real_distribution<double> U(-5, 5), M(0, 1.5), A(0, 2 * M_PI);
  for (int k = 0; k < 2000; ++k) {
    const double mu = k % 10 == 0 ? 0.0 : M(gen);
    const Vec3 tau(U(gen), U(gen), U(gen));
    const Vec3 P = project_cone(tau, mu);
    REQUIRE(in_cone(P, mu));
    REQUIRE((project_cone(P, mu) - P).norm() <= 1e-12 * (1 + P.norm()));
    // (tau - P(tau)) . (R - P(tau)) <= 0 for every R of the cone: a point of the cone's surface
    // in any direction, and one inside.
    const double Rn = std::abs(U(gen)), phi = A(gen);
    const Vec3 R(mu * Rn * std::cos(phi), mu * Rn * std::sin(phi), Rn);
    REQUIRE((tau - P).dot(R - P) <= 1e-10);
    REQUIRE((tau - P).dot(0.5 * R - P) <= 1e-10);
    // The projection is the nearest point: no cone point of this sample is nearer.
    REQUIRE((tau - P).norm() <= (tau - R).norm() + 1e-12);
  }
}

TEST_CASE("the circular cone reduces to the 2D wedge when the slip is planar", "[law][3d]") {
  std::mt19937 gen(44);
  std::uniform_real_distribution<double> U(-5, 5), M(0, 1.5), A(0, 2 * M_PI);
  for (int k = 0; k < 500; ++k) {
    const double mu = M(gen), t = U(gen), n = U(gen), phi = A(gen);
    // The 2D problem (t, n) turned about the normal by phi: the 3D projection is the 2D one turned.
    const Vec2 P2 = project_cone(Vec2(t, n), mu);
    const Vec3 P3 = project_cone(Vec3(t * std::cos(phi), t * std::sin(phi), n), mu);
    REQUIRE(cone_branch(Vec3(t * std::cos(phi), t * std::sin(phi), n), mu) == cone_branch(Vec2(t, n), mu));
    REQUIRE((P3 - Vec3(P2[0] * std::cos(phi), P2[0] * std::sin(phi), P2[1])).norm() <= 1e-12 * (1 + P2.norm()));
    const Vec2 s2 = modified_velocity(Vec2(t, n), mu);
    const Vec3 s3 = modified_velocity(Vec3(t * std::cos(phi), t * std::sin(phi), n), mu);
    REQUIRE(s3[2] == Approx(s2[1]).epsilon(1e-14));
  }
}

TEST_CASE("3D |v_t|: exact on Pythagorean triples, neither underflows nor overflows", "[law][3d]") {
  for (double scale : {1.0, 1e-200, 1e200, 1e-310}) {  // 1e-310: subnormal
    INFO("scale " << scale);
    CHECK(tangential_norm(Eigen::Vector3d(3 * scale, -4 * scale, 7.0)) == Approx(5 * scale).epsilon(1e-15));
    CHECK(tangential_norm(Eigen::Vector3d(-4 * scale, 3 * scale, -1.0)) == Approx(5 * scale).epsilon(1e-15));
  }
  CHECK(tangential_norm(Eigen::Vector3d(0.0, 0.0, 1.0)) == 0.0);
  CHECK(tangential_norm(Eigen::Vector2d(-2.5, 1.0)) == 2.5);  // 2D: exactly |v_0|
}

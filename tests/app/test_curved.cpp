// Curved rigid foundations (issue 16, interface.circle) against closed forms coded here,
// independently of rccm:
// - Lame's plane-strain annulus a < r < b filling a rigid circular hole r = b (side "inside"),
//   a pressure p on its bore r = a. Pushed out (p > 0), the wall holds u_r(b) = 0 by
//   unilateral contact and Rbar_n / a_i is the contact pressure -sigma_rr(b); sucked in
//   (p < 0), the contact opens and the bond's springs hold the annulus, the Robin condition
//   sigma_rr(b) = -Cn u_r(b). The nodal u_r and the interface quantity converge at second
//   order; every contact pair carries the same numbers (the per-node radial frames);
// - plane Hertz contact of an elastic cylinder of radius R1 in a rigid circular seat of
//   radius R2 > R1 (side "inside"), frictionless and unbonded, the gap from the geometry: the
//   peak pressure, the contact half-width and the pressure profile against Hertz with
//   1/R = 1/R1 - 1/R2;
// - config/coating-curved.cfg (a coating peeled from a rigid cylinder, side "outside"): the
//   invariants at every step and a front that runs down the arc from the pulled end; and the
//   same problem turned about a point (mesh, the circle's centre and the pull) giving the
//   same beta, u and Rbar at every pair.
#include "helpers.hpp"
#include "rccm/app/simulation.hpp"
#include "rccm/fem/elasticity.hpp"
#include "rccm/model/body_state.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>

using namespace rccm;

namespace {

const std::string meshes = std::string(RCCM_SOURCE_DIR) + "/tests/meshes/curved/";

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// The last accepted state of a run of `cfg` (no files), and its bulk on `model` (built from
/// the same config).
struct FinalState {
  InterfaceState interface;
  BodyState body;
};

FinalState run_to_end(const Config& cfg, const Model& model) {
  FinalState out;
  RunOptions o;
  o.observer = [&](const AcceptedStep& a) {
    out.interface = a.state;
    out.body = body_state(model, a.state);
  };
  const RunResult r = Simulation(cfg, o).run();
  REQUIRE(r.stopped.empty());
  return out;
}

// ---------------------------------------------------------------------------------------
// Lame, plane strain. u_r = A r + B / r, so eps_rr = A - B / r^2, eps_thth = A + B / r^2 and
//   sigma_rr = (lambda + 2 mu) eps_rr + lambda eps_thth = 2 (lambda + mu) A - 2 mu B / r^2.
// The pressure p on the bore pushes into the body: sigma_rr(a) = -p. At the wall r = b the
// circle's normal n points to the centre (from the wall into the body), so u_n = -u_r and the
// force of the wall on the body is r_n n, a traction -(r_n / a_i) e_r: sigma_rr(b) = -r_n / a_i.
// (i) p > 0, contact closed: u_r(b) = 0, B = -A b^2, and sigma_rr(a) = -p gives
//       A = -p / (2 (lambda + mu) + 2 mu b^2 / a^2),
//     the contact pressure Rbar_n / a_i = -sigma_rr(b) = -2 (lambda + 2 mu) A (= p when b = a).
// (ii) p < 0, contact open (Rbar = 0), beta = 1: r_n = Radh_n = -a_i Cn u_n = a_i Cn u_r(b), so
//       sigma_rr(b) = -Cn u_r(b)  (tension as the annulus shrinks away from the wall),
//     with sigma_rr(a) = -p: two linear equations in A, B (Cramer's rule).
struct PlaneLame {
  double lambda = 0, mu = 0, A = 0, B = 0;
  /// k < 0: the closed rigid wall, u_r(b) = 0; k >= 0: the bond sigma_rr(b) = -k u_r(b).
  PlaneLame(double E, double nu, double a, double b, double p, double k) {
    lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
    mu = E / (2 * (1 + nu));
    if (k < 0) {
      A = -p / (2 * (lambda + mu) + 2 * mu * b * b / (a * a));
      B = -A * b * b;
    } else {
      // [m11 m12; m21 m22] [A; B] = [-p; 0]
      const double m11 = 2 * (lambda + mu), m12 = -2 * mu / (a * a);
      const double m21 = 2 * (lambda + mu) + k * b, m22 = -2 * mu / (b * b) + k / b;
      const double det = m11 * m22 - m12 * m21;
      A = -p * m22 / det;
      B = p * m21 / det;
    }
  }
  double u(double r) const { return A * r + B / r; }
  double srr(double r) const { return 2 * (lambda + mu) * A - 2 * mu * B / (r * r); }
};

struct LameLevel {
  double h = 0;           // chord of a cell along the wall, mm
  double u = 0;           // max over the nodes of |u - u_r exact e_r| / max |u_r exact|
  double u_theta = 0;     // max |u_theta| / max |u_r exact| (a part of u)
  double wall = 0;        // mean over the pairs: Rbar_n / a_i (p > 0, MPa) or u_n (p < 0, mm)
  double wall_exact = 0;  // -sigma_rr(b) or -u_r(b)
  double wall_error = 0;  // |wall / wall_exact - 1|
  double spread = 0;      // (max - min) / |mean| of that quantity over the pairs
  double stress = 0;      // sigma_rr(b) = -r_n / a_i from the interface force (mean), MPa
  double stress_exact = 0;
  double other = 0;       // p > 0: max |u_n| / max |u_r exact| (no penetration, no opening);
                          // p < 0: max |Rbar| (the contact is open)
  double tangential = 0;  // max |u_t| / max |u_r exact| + max |Rbar_t| / max |Rbar_n|
  double frame = 0;       // max |n + x / |x|| + |t - (n_y, -n_x)| over the pairs
  double seconds = 0;
  int pairs = 0;
};

/// The annulus a = 1 < r < b = 2 of tests/meshes/curved/annulus.geo on a polar grid of
/// 4 * 2^level cells across and 24 * 2^level around, E = 1000, nu = 0.3, in a rigid hole of
/// radius b, bonded (Cn = Ct = 500 MPa/mm: Cn b / E = 1, the bond's compliance matters),
/// beta held at 1, a pressure p on its bore.
LameLevel lame_level(int level, bool quads, double p) {
  const auto start = std::chrono::steady_clock::now();
  const double a = 1, b = 2, E = 1000, nu = 0.3, Cn = 500;
  std::ostringstream text;
  text << std::setprecision(17) << "mesh = { file = \"" << meshes << "annulus.geo\"; parameters = { a = " << a
       << "; b = " << b << "; nr = " << (4 << level) << "; nq = " << (6 << level) << "; quads = " << (quads ? 1 : 0)
       << "; }; };\n"
       << "material = { E = " << E << "; nu = " << nu << "; hypothesis = \"plane_strain\"; };\n"
       << "interface = { boundary = \"outer\"; circle = { centre = [0.0, 0.0]; radius = " << b
       << "; side = \"inside\"; }; Cn = " << Cn << "; Ct = " << Cn << "; w = 1.0; mu = 0.3; };\n"
       << "loads = ( { node_set = \"inner\"; type = \"pressure\"; value = " << p << "; } );\n"
       << "time = { T = 1.0; steps = 1; };\nintegrator = { method = \"contact-only\"; };\n";
  const Config cfg = test::config_from_text(text.str());
  const Model model = test::make_model(cfg);
  const FinalState s = run_to_end(cfg, model);
  const PlaneLame exact(E, nu, a, b, p, p > 0 ? -1.0 : Cn);
  const Mesh& mesh = model.mesh();
  LameLevel e;
  const double scale = std::max(std::abs(exact.u(a)), std::abs(exact.u(b)));
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    const Eigen::Vector3d& x = mesh.nodes[n];
    const double r = x.norm(), ux = s.body.u[mesh.dof(n, 0)], uy = s.body.u[mesh.dof(n, 1)];
    const double ur = (x.x() * ux + x.y() * uy) / r, ut = (x.x() * uy - x.y() * ux) / r;
    e.u = std::max(e.u, std::hypot(ur - exact.u(r), ut) / scale);
    e.u_theta = std::max(e.u_theta, std::abs(ut) / scale);
  }
  const Interface& I = model.interface();
  e.pairs = I.size();
  e.h = 2 * b * std::sin(M_PI / (24 << level));
  std::vector<double> q;
  double Rn_max = 0, Rt_max = 0, ut_max = 0;
  for (int i = 0; i < I.size(); ++i) {
    const ContactPair& c = I.pairs[i];
    const double Rt = s.interface.Rbar[2 * i], Rn = s.interface.Rbar[2 * i + 1];
    const double ut = s.interface.u[2 * i], un = s.interface.u[2 * i + 1];
    q.push_back(p > 0 ? Rn / c.measure : un);
    e.stress -= s.body.r[2 * i + 1] / c.measure / I.size();
    e.other = std::max(e.other, p > 0 ? std::abs(un) / scale : std::max(std::abs(Rn), std::abs(Rt)));
    Rn_max = std::max(Rn_max, std::abs(Rn));
    Rt_max = std::max(Rt_max, std::abs(Rt));
    ut_max = std::max(ut_max, std::abs(ut));
    const Eigen::Vector3d& x = mesh.nodes[c.node];
    const Eigen::Vector3d n = c.frame.n, t = c.frame.t1;
    e.frame = std::max(e.frame, (n + x / x.norm()).norm() + (t - Eigen::Vector3d(n.y(), -n.x(), 0)).norm());
  }
  e.tangential = ut_max / scale + (Rn_max > 0 ? Rt_max / Rn_max : 0.0);
  double sum = 0;
  for (double v : q) sum += v;
  e.wall = sum / q.size();
  e.spread = (*std::max_element(q.begin(), q.end()) - *std::min_element(q.begin(), q.end())) / std::abs(e.wall);
  e.wall_exact = p > 0 ? -exact.srr(b) : -exact.u(b);
  e.wall_error = std::abs(e.wall / e.wall_exact - 1);
  e.stress_exact = exact.srr(b);
  e.seconds = seconds_since(start);
  return e;
}

}  // namespace

TEST_CASE("Lame's annulus in a rigid circular hole: pushed out, the wall's contact pressure, sucked in, the "
          "bond's Robin condition, second order, the same at every contact pair",
          "[curved]") {
  const auto start = std::chrono::steady_clock::now();
  for (double p : {1.0, -1.0})
    for (bool quads : {true, false}) {
      std::cout << "Lame in a hole, p = " << p << (quads ? ", Q4" : ", T3") << ": pairs, h, max |u_r error|/max|u|, order, "
                << (p > 0 ? "Rbar_n/a" : "u_n") << " FE / exact, relative error, order, spread over the pairs, s\n";
      std::vector<LameLevel> levels;
      for (int level = 0; level <= 3; ++level) {
        levels.push_back(lame_level(level, quads, p));
        const LameLevel& e = levels.back();
        const bool coarser = levels.size() > 1;
        const LameLevel* c = coarser ? &levels[levels.size() - 2] : nullptr;
        const double order_u = coarser ? std::log(c->u / e.u) / std::log(c->h / e.h) : 0.0;
        const double order_w = coarser ? std::log(c->wall_error / e.wall_error) / std::log(c->h / e.h) : 0.0;
        std::cout << std::setprecision(6) << "  " << e.pairs << "  " << e.h << "  " << e.u << "  " << order_u << "  "
                  << e.wall << " / " << e.wall_exact << "  " << e.wall_error << "  " << order_w << "  " << e.spread
                  << "  " << e.seconds << "\n";
        INFO("p = " << p << (quads ? " Q4" : " T3") << ", level " << level << ": u error " << e.u << ", wall "
                    << e.wall << " vs " << e.wall_exact << ", spread " << e.spread << ", u_theta " << e.u_theta
                    << ", tangential " << e.tangential << ", other " << e.other << ", frame " << e.frame);
        CHECK(e.frame < 1e-12);        // radial frames: n to the centre, t = (n_y, -n_x)
        CHECK(e.spread < 1e-8);        // every pair alike: the polar grid is the same turned by a cell
        // No twist on the quadrilaterals (the grid is its own mirror image about a radial
        // line); the triangles all lean one way (no mirror symmetry) and twist the annulus
        // by a discretization error that converges with u (u_theta is part of u's error).
        if (quads) CHECK(e.u_theta < 1e-9);
        CHECK(e.tangential < 1e-9);    // no slip, no tangential force
        if (p > 0) CHECK(e.other < 1e-12);   // the wall: u_n = 0 at every pair, no penetration
        else CHECK(e.other == 0.0);          // the contact is open: the springs alone hold it
        CHECK(e.wall > 0);  // pushed: Rbar_n > 0 (compression); sucked: u_n > 0 (it opens)
        // sigma_rr(b) from the interface force: -(contact pressure) or the springs' tension
        CHECK(e.stress == Approx(e.stress_exact).epsilon(3 * e.wall_error + 1e-12));
        if (coarser) {
          CHECK(order_u > 1.8);  // nodal displacement: second order
          CHECK(order_w > 1.8);  // the interface quantity too
        }
      }
      CHECK(levels.back().u < 1e-3);
      CHECK(levels.back().wall_error < 1e-3);
    }
  std::cout << "Lame in a hole: " << seconds_since(start) << " s\n";
}

namespace {

// ---------------------------------------------------------------------------------------
// Plane Hertz contact (Johnson, Contact Mechanics, s4.2-4.3 and 5.2): an elastic cylinder of
// radius R1 (E, nu; plane strain, E* = E / (1 - nu^2) against a rigid body) pressed by a force
// P per unit length into a rigid cylindrical seat of radius R2 > R1 (a conforming contact):
// the relative curvature 1/R = 1/R1 - 1/R2, and, while the half-width b is small against R1,
//   b^2 = 4 P R / (pi E*),  p(s) = p0 sqrt(1 - s^2 / b^2),  p0 = 2 P / (pi b).
// The model: the right half of the disk (u_x = 0 on x = 0), centred at the origin, the seat's
// centre at (0, R2 - R1) so that the two touch at (0, -R1); the gap of each contact node is its
// distance to the seat, R2 - |x - c| (from the geometry), P / 2 down at the top. Frictionless
// and unbonded: mu = 0, beta0 = 0 (contact-only). s is the arc length from the bottom.
struct HertzSeat {
  double h = 0;                // cell length along the contact arc, mm
  double peak = 0, p0 = 0;     // the pressure at the bottom pair (Rbar_n / a), and Hertz's p0
  double b = 0;                // Hertz's half-width
  double last = 0;             // s of the last pair in contact
  double moment = 0;           // 2 sqrt(sum F s^2 / sum F): b for the elliptic profile
  double l2 = 0;               // relative L2 (tributary) error of Rbar_n / a against p(s)
  double force = 0, force_exact = 0;  // vertical resultant of the contact forces, P / 2
  double complementarity = 0;  // max |g Rbar_n| / (max Rbar_n max |u_n|), and penetration
  double penetration = 0;      // max(0, -g) / max |u_n|
  double friction = 0;         // max |Rbar_t|
  double seconds = 0;
};

HertzSeat hertz_seat(int refine, double b) {
  const auto start = std::chrono::steady_clock::now();
  const double R1 = 10, R2 = 12, E = 1000, nu = 0.3, thc = 0.3;
  const int nc = 24;
  const double Es = E / (1 - nu * nu), R = 1 / (1 / R1 - 1 / R2);
  const double P = M_PI * Es * b * b / (4 * R);
  std::ostringstream text;
  text << std::setprecision(17) << std::showpoint << "mesh = { file = \"" << meshes << "half_disk.geo\"; refine = " << refine
       << "; parameters = { R1 = " << R1 << "; thc = " << thc << "; nc = " << nc << "; }; };\n"
       << "material = { E = " << E << "; nu = " << nu << "; hypothesis = \"plane_strain\"; };\n"
       << "interface = { boundary = \"contact\"; circle = { centre = [0.0, " << R2 - R1 << "]; radius = " << R2
       << "; side = \"inside\"; }; Cn = 1000.0; Ct = 1000.0; w = 0.0; mu = 0.0; beta0 = 0.0; };\n"
       << "loads = ( { node_set = \"axis\"; type = \"displacement\"; component = \"x\"; value = 0.0; },\n"
       << "          { node_set = \"top\"; type = \"force\"; component = \"y\"; value = " << -P / 2 << "; } );\n"
       << "time = { T = 1.0; steps = 1; };\nintegrator = { method = \"contact-only\"; };\n";
  const Config cfg = test::config_from_text(text.str());
  const Model model = test::make_model(cfg);
  const FinalState s = run_to_end(cfg, model);
  HertzSeat out;
  out.b = b;
  out.p0 = 2 * P / (M_PI * b);
  out.force_exact = P / 2;
  out.h = R1 * thc / (nc << refine);
  const Interface& I = model.interface();
  double Rn_max = 0, un_max = 0;
  for (int i = 0; i < I.size(); ++i) Rn_max = std::max(Rn_max, s.interface.Rbar[2 * i + 1]);
  for (int i = 0; i < I.size(); ++i) un_max = std::max(un_max, std::abs(s.interface.u[2 * i + 1]));
  double num = 0, den = 0, F = 0, Fs2 = 0;
  for (int i = 0; i < I.size(); ++i) {
    const ContactPair& c = I.pairs[i];
    const Eigen::Vector3d& x = model.mesh().nodes[c.node];
    const double s_arc = R1 * std::atan2(x.x(), -x.y());
    const double Rt = s.interface.Rbar[2 * i], Rn = s.interface.Rbar[2 * i + 1], g = c.g0 + s.interface.u[2 * i + 1];
    const double p = Rn / c.measure, exact = out.p0 * std::sqrt(std::max(0.0, 1 - s_arc * s_arc / (b * b)));
    num += c.measure * (p - exact) * (p - exact);
    den += c.measure * exact * exact;
    F += Rn, Fs2 += Rn * s_arc * s_arc;
    out.force += Rn * c.frame.n.y() + Rt * c.frame.t1.y();
    out.friction = std::max(out.friction, std::abs(Rt));
    out.penetration = std::max(out.penetration, std::max(0.0, -g) / un_max);
    out.complementarity = std::max(out.complementarity, std::abs(g * Rn) / (Rn_max * un_max));
    if (Rn > 1e-9 * Rn_max) out.last = std::max(out.last, s_arc);
    if (std::abs(x.x()) < 1e-12) out.peak = p;
  }
  out.l2 = std::sqrt(num / den);
  out.moment = 2 * std::sqrt(Fs2 / F);
  out.seconds = seconds_since(start);
  return out;
}

void print_hertz(const HertzSeat& r, const HertzSeat* coarser) {
  const double order = coarser ? std::log(coarser->l2 / r.l2) / std::log(coarser->h / r.h) : 0.0;
  std::cout << std::setprecision(6) << "  " << r.h / r.b << "  " << r.peak << " / " << r.p0 << "  "
            << 100 * (r.peak / r.p0 - 1) << " %  " << r.last / r.b << "  " << r.moment / r.b << "  " << r.l2 << "  "
            << order << "  " << r.seconds << "\n";
}

/// `model_error`: Hertz's own error allowed in the half-width, a fraction of b.
void check_hertz(const HertzSeat& r, double model_error = 0.0) {
  INFO("h/b = " << r.h / r.b << ": peak " << r.peak << " vs " << r.p0 << ", last " << r.last << ", moment " << r.moment
                << ", L2 " << r.l2 << ", force " << r.force << " vs " << r.force_exact);
  CHECK(r.force == Approx(r.force_exact).epsilon(1e-9));  // the seat carries the load
  CHECK(r.friction == 0.0);                               // frictionless, unbonded
  CHECK(r.penetration < 1e-9);                            // Signorini
  CHECK(r.complementarity < 1e-9);
  CHECK(std::abs(r.last - r.b) <= r.h + model_error * r.b + 1e-9);  // the contact ends within a cell of b
}

}  // namespace

TEST_CASE("Hertz: a cylinder pressed into a rigid circular seat, the gap from the geometry: peak pressure, "
          "half-width and profile converge to Hertz with 1/R = 1/R1 - 1/R2",
          "[curved]") {
  const auto start = std::chrono::steady_clock::now();
  // b / R1 = 0.05: Hertz's own error (the disk is no half-space) is a few 0.1 % here (see the
  // [.long] study below); h from b/4 to b/16.
  std::cout << "Hertz in a seat, R1 = 10, R2 = 12, b = 0.5: h/b, peak FE / Hertz, error, last pair in contact / b, "
               "moment estimate of b / b, L2 error of the profile, order, s\n";
  std::vector<HertzSeat> runs;
  for (int refine = 0; refine <= 2; ++refine) {
    runs.push_back(hertz_seat(refine, 0.5));
    print_hertz(runs.back(), refine ? &runs[runs.size() - 2] : nullptr);
    check_hertz(runs.back());
  }
  for (std::size_t k = 1; k < runs.size(); ++k) {
    INFO("refine " << k);
    CHECK(runs[k].l2 < 0.6 * runs[k - 1].l2);                                      // about first order, or better
    CHECK(std::abs(runs[k].peak / runs[k].p0 - 1) < std::abs(runs[k - 1].peak / runs[k - 1].p0 - 1));
    CHECK(std::abs(runs[k].moment / runs[k].b - 1) < std::abs(runs[k - 1].moment / runs[k - 1].b - 1));
  }
  CHECK(std::abs(runs.back().peak / runs.back().p0 - 1) < 0.01);
  CHECK(std::abs(runs.back().moment / runs.back().b - 1) < 0.01);
  CHECK(runs.back().l2 < 0.02);
  std::cout << "Hertz in a seat: " << seconds_since(start) << " s\n";
}

TEST_CASE("Hertz in a seat, the long study: h down to b/64 (b/R1 = 0.05) and b/128 (b/R1 = 0.1), about 40 s",
          "[.long][curved_long]") {
  for (double b : {0.5, 1.0}) {
    std::cout << "Hertz in a seat, R1 = 10, R2 = 12, b = " << b
              << ": h/b, peak FE / Hertz, error, last pair / b, moment b / b, L2 error, order, s\n";
    std::vector<HertzSeat> runs;
    for (int refine = 0; refine <= 4; ++refine) {
      runs.push_back(hertz_seat(refine, b));
      print_hertz(runs.back(), refine ? &runs[runs.size() - 2] : nullptr);
      check_hertz(runs.back(), 0.02);
    }
    // Hertz's own error grows with b / R1 (the disk is no half-space): on the finest meshes the
    // peak is 0.3 % (b/R1 = 0.05) and 1.1 % (b/R1 = 0.1) above Hertz, the moment half-width
    // 0.55 % and 1.1 % below, where the FE values settle.
    CHECK(std::abs(runs.back().peak / runs.back().p0 - 1) < (b < 0.75 ? 0.005 : 0.015));
  }
}

namespace {

// ---------------------------------------------------------------------------------------
// config/coating-curved.cfg

/// beta in [0, 1] and non-increasing at every node and step, the committed contact residuals,
/// friction-free wherever beta = 1; when each pair first falls below 1/2.
struct StepChecks {
  Eigen::VectorXd previous;
  std::vector<double> half_time;
  int steps = 0;
  double worst_residual = 0, worst_increase = 0, beta_min = 1, beta_max = 0, bonded_friction = 0;
  double max_compression = 0;

  void operator()(const AcceptedStep& a) {
    const Eigen::VectorXd& beta = a.state.beta;
    if (previous.size() == 0) previous = beta, half_time.assign(beta.size(), -1);
    worst_increase = std::max(worst_increase, (beta - previous).maxCoeff());
    beta_min = std::min(beta_min, beta.minCoeff());
    beta_max = std::max(beta_max, beta.maxCoeff());
    worst_residual = std::max(worst_residual, a.residuals.max());
    for (Eigen::Index i = 0; i < beta.size(); ++i) {
      if (half_time[i] < 0 && beta[i] < 0.5) half_time[i] = a.t;
      if (beta[i] == 1.0) bonded_friction = std::max(bonded_friction, std::abs(a.state.Rbar[2 * i]));
      max_compression = std::max(max_compression, a.state.Rbar[2 * i + 1]);
    }
    previous = beta;
    ++steps;
  }
};

Config coating_curved(const std::vector<std::string>& overrides = {}) {
  return load_config(test::shipped("coating-curved.cfg"), overrides);
}

}  // namespace

TEST_CASE("config/coating-curved.cfg: a coating peeled from a rigid cylinder debonds from its pulled end along the "
          "arc",
          "[curved]") {
  const auto start = std::chrono::steady_clock::now();
  const Config cfg = coating_curved();
  const Model model = test::make_model(cfg);
  StepChecks checks;
  RunOptions o;
  o.observer = std::ref(checks);
  const RunResult r = Simulation(cfg, o).run();
  REQUIRE(r.stopped.empty());
  const Interface& I = model.interface();
  // The pairs by angle about the cylinder's axis: the pulled end at 90 degrees.
  std::vector<double> angle;
  for (const ContactPair& c : I.pairs) {
    const Eigen::Vector3d& x = model.mesh().nodes[c.node];
    angle.push_back(std::atan2(x.y(), x.x()) * 180 / M_PI);
    CHECK(c.frame.n.dot(x.normalized()) == Approx(1.0).epsilon(1e-12));  // "outside": n points away from the axis
    CHECK(std::abs(c.g0) < 1e-9);                                          // bonded on the circle
  }
  INFO(checks.steps << " steps, worst residual " << checks.worst_residual);
  CHECK(checks.beta_min >= 0.0);
  CHECK(checks.beta_max <= 1.0);
  CHECK(checks.worst_increase <= 0.0);
  CHECK(checks.worst_residual <= 1e-8);
  CHECK(checks.bonded_friction == 0.0);   // no friction while fully bonded
  CHECK(checks.max_compression > 0.0);    // ahead of the front the layer presses on the cylinder
  CHECK(r.energy.relative_error() < 1e-4);
  CHECK(r.warnings.empty());  // no note of large deformation: |grad u| reaches 0.141 in one cell of 240
  // The front: pairs lose their adhesion in order of decreasing angle (from the pulled end),
  // the debonded part is one run from the pulled end that grows through the output times
  // (2, 5 and 10 s) and has not reached the far end.
  std::vector<int> order(I.size());
  for (int i = 0; i < I.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](int i, int j) { return angle[i] > angle[j]; });
  REQUIRE(angle[order[0]] == Approx(90.0));
  REQUIRE(checks.half_time[order[0]] >= 0);
  for (int k = 1; k < I.size(); ++k)
    if (checks.half_time[order[k]] >= 0) {
      INFO("pair at " << angle[order[k]] << " degrees");
      CHECK(checks.half_time[order[k - 1]] >= 0);
      CHECK(checks.half_time[order[k]] >= checks.half_time[order[k - 1]]);
    }
  REQUIRE(r.snapshots.size() == 3);
  std::vector<double> front;  // the angle down to which the interface is debonded
  for (const Snapshot& s : r.snapshots) {
    double lowest = 90.0;
    for (int i = 0; i < I.size(); ++i)
      if (s.beta[i] < 0.5) lowest = std::min(lowest, angle[i]);
    front.push_back(lowest);
  }
  std::cout << "coating-curved: " << checks.steps << " steps, debonded down to " << front[0] << ", " << front[1] << ", "
            << front[2] << " degrees at t = 2, 5, 10 s; debonded length " << r.snapshots[0].debonded_length << ", "
            << r.snapshots[1].debonded_length << ", " << r.snapshots[2].debonded_length << " mm; "
            << seconds_since(start) << " s\n";
  CHECK(front[0] < 90.0);
  CHECK(front[1] < front[0]);
  CHECK(front[2] < front[1]);
  CHECK(front[2] > 0.0);  // the far end (-30 degrees) still bonded
  CHECK(r.snapshots[2].debonded_length > r.snapshots[1].debonded_length);
}

TEST_CASE("config/coating-curved.cfg lifted 4 mm instead of 1: the run notes once where it leaves small strains",
          "[curved]") {
  // The pulled end's cells pass |grad u| = 0.15 (the note's limit) over 1 % of the coating's
  // volume (its rule) at some accepted step: the run's one warning names the coating, the
  // limit and a time at which the coating is beyond, within T / 200 (the checks' spacing)
  // and a step of the first such step.
  const Config cfg = coating_curved({"loads.[0].value=4.0"});
  // A model of its own gives the run's bulk: in 2D K0's springs stay at beta = 1 (with
  // solver.springs_follow_beta, the 3D default, only the run's own model could).
  const Model model = test::make_model(cfg);
  const SmallStrainCheck small_strains(model.mesh());
  double first = -1, largest_dt = 0;
  std::vector<std::pair<double, double>> fraction;  // (t, share of the coating beyond) at each step
  RunOptions o;
  o.observer = [&](const AcceptedStep& a) {
    const DeformationExcess e = small_strains(body_state(model, a.state).u, 0.15);
    if (first < 0 && e.fraction > 0.01) first = a.t;
    fraction.emplace_back(a.t, e.fraction);
    largest_dt = std::max(largest_dt, a.dt);
  };
  const RunResult r = Simulation(cfg, o).run();
  REQUIRE(r.stopped.empty());
  REQUIRE(first > 0);
  REQUIRE(r.warnings.size() == 1);
  CHECK_THAT(r.warnings[0], Catch::StartsWith("t = ") && Catch::Contains(" s: the displacement gradient |grad u| exceeds 0.15 over ") &&
                                Catch::Contains("of body 'coating'"));
  const double t_note = std::stod(r.warnings[0].substr(4));
  INFO("first beyond at t = " << first << ", noted at t = " << t_note);
  CHECK(t_note >= first);
  CHECK(t_note <= first + cfg.time.T / 50 + largest_dt);  // checked every T/50 (io/recorder.cpp)
  const auto at = std::find_if(fraction.begin(), fraction.end(), [&](const auto& f) { return std::abs(f.first - t_note) < 1e-5; });
  REQUIRE(at != fraction.end());
  CHECK(at->second > 0.01);
  CHECK(r.strain_checks_left_out == 0);  // the body's solves: a sliver of the run
}

TEST_CASE("the small-strain checks given no share of the run: checked only where the body is solved anyway",
          "[curved]") {
  // The same lifted coating, its checks' solves allowed none of the run's time (as for a body
  // whose solve takes minutes): checked at step 0 (its frame), at the output times 2 and 5 s
  // and at T, whose solves are made anyway; each check due in between is left out, and the
  // note comes at the first of those times beyond the limit. Allowed all of the run: every
  // check due is made, the note within T / 50 of the first step beyond.
  const Config cfg = coating_curved({"loads.[0].value=4.0"});
  RunOptions none;
  none.strain_check_share = 0;
  const RunResult r = Simulation(cfg, none).run();
  RunOptions all;
  all.strain_check_share = std::numeric_limits<double>::infinity();
  const RunResult s = Simulation(cfg, all).run();
  REQUIRE(r.stopped.empty());
  REQUIRE(r.warnings.size() == 1);
  REQUIRE(s.warnings.size() == 1);
  const double t_none = std::stod(r.warnings[0].substr(4)), t_all = std::stod(s.warnings[0].substr(4));
  INFO("noted at t = " << t_all << " s with every check, at " << t_none << " s with none of the run for them");
  CHECK((t_none == 2.0 || t_none == 5.0 || t_none == cfg.time.T));
  CHECK(t_none >= t_all);
  CHECK(t_all < t_none);  // beyond the limit before 2 s, 5 s or T: within T / 50 of its first step
  CHECK(r.strain_checks == 1 + int(t_none >= 2.0) + int(t_none >= 5.0) + int(t_none >= cfg.time.T));
  CHECK(r.strain_checks_left_out >= 49 * t_none / cfg.time.T - 1);  // due every T / 50 until the note
  CHECK(r.strain_checks_left_out <= 50 * t_none / cfg.time.T);
  CHECK(r.body_solves == 4);  // step 0, 2 s, 5 s, T: none for a check
  CHECK(s.strain_checks_left_out == 0);
  CHECK(s.strain_checks >= 50 * t_all / cfg.time.T);
}

TEST_CASE("a curved interface turned about a point (mesh, circle centre and pull): the same beta, u and Rbar at every "
          "pair",
          "[curved]") {
  // config/coating-curved.cfg on 20 x 2 cells, turned about (5, -3): the mesh by mesh.rotation,
  // the circle's centre (global) and the pull of the tip (its x and y components) by hand.
  // Fixed steps, so that every run takes the same steps (adaptive steps are chosen on
  // round-off and the runs then differ by the integrator's error, 1e-6 in beta at rtol 1e-9
  // as the front crosses a node): explicit Euler, dt = 0.02 s, up to T = 6 s (beyond it a
  // sliding node with beta ~ 1e-4 makes Euler unstable and amplifies round-off; until then
  // dt C u^2 / alpha exceeds 2 only as a node's beta is clamped to 0). The pull keeps the
  // shipped rate, 1 mm in 10 s.
  const auto start = std::chrono::steady_clock::now();
  const auto turned = [](double degrees) {
    const double c = std::cos(degrees * M_PI / 180), s = std::sin(degrees * M_PI / 180);
    const double ox = 5.0, oy = -3.0;  // the centre (0, 0) turned about (ox, oy)
    std::ostringstream centre, loads;
    centre << std::setprecision(17) << std::showpoint << "interface.circle.centre=[" << ox + c * (0 - ox) - s * (0 - oy)
           << ", " << oy + s * (0 - ox) + c * (0 - oy) << "]";
    loads << std::setprecision(17) << std::showpoint
          << "loads=({node_set=\"tip\"; type=\"displacement\"; component=\"x\"; table=((0.0, 0.0), (10.0, " << -1.0 * s
          << "));}, {node_set=\"tip\"; type=\"displacement\"; component=\"y\"; table=((0.0, 0.0), (10.0, " << 1.0 * c
          << "));})";
    return Simulation(coating_curved({"mesh.parameters.na=20", "mesh.parameters.nt=2", "mesh.origin=[5.0, -3.0]",
                                      "mesh.rotation=" + std::to_string(degrees), centre.str(), loads.str(),
                                      "integrator.method=euler", "time.T=6.0", "time.steps=300",
                                      "output.times=[2.0, 4.0]"}))
        .run();
  };
  const RunResult r0 = turned(0.0);
  REQUIRE(r0.snapshots.back().beta.minCoeff() < 0.5);   // a front has formed
  REQUIRE(r0.snapshots.back().beta.maxCoeff() == 1.0);  // and not run through
  REQUIRE(r0.snapshots.back().Rbar.maxCoeff() > 0.0);   // contact ahead of it
  for (double degrees : {30.0, 217.0}) {
    const RunResult r = turned(degrees);
    REQUIRE(r.snapshots.size() == r0.snapshots.size());
    for (std::size_t k = 0; k < r.snapshots.size(); ++k) {
      const Snapshot &a = r0.snapshots[k], &b = r.snapshots[k];
      INFO("turned " << degrees << " degrees, t = " << a.t);
      std::cout << "coating-curved turned " << degrees << " degrees, t = " << a.t << ": max |dbeta| "
                << (a.beta - b.beta).cwiseAbs().maxCoeff() << ", max |du|/max|u| "
                << (a.u - b.u).cwiseAbs().maxCoeff() / a.u.cwiseAbs().maxCoeff() << ", max |dRbar|/max|Rbar| "
                << (a.Rbar - b.Rbar).cwiseAbs().maxCoeff() / a.Rbar.cwiseAbs().maxCoeff() << "\n";
      CHECK((a.beta - b.beta).cwiseAbs().maxCoeff() <= 1e-10);
      CHECK((a.u - b.u).cwiseAbs().maxCoeff() <= 1e-10 * a.u.cwiseAbs().maxCoeff());
      CHECK((a.Rbar - b.Rbar).cwiseAbs().maxCoeff() <= 1e-9 * a.Rbar.cwiseAbs().maxCoeff());
    }
    CHECK(r.energy.external_work == Approx(r0.energy.external_work).epsilon(1e-10));
  }
  std::cout << "coating-curved turned: " << seconds_since(start) << " s\n";
}

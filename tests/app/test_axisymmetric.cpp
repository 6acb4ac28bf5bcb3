// Axisymmetry (issue 16) against closed forms coded here, independently of rccm:
// - Lame's thick cylinder under internal pressure, its outer surface bonded to a rigid wall
//   (a compliant bond: sigma_rr(b) = -Cn u_r(b)), or pressed against it (Signorini: u_r(b) = 0),
//   u_r, sigma_rr, sigma_thth, sigma_zz converging under uniform refinement, Q4 and T3;
// - the shear-lag load transfer of a fibre bonded to a rigid matrix, E a^2 u'' = 2 a Ct u,
//   whose error is the fibre's own shear compliance (-Ct a / (8 G)), gone once the interface
//   compliance is taken in series with it, 1/Ct_eff = 1/Ct + a / (4 G); pulled by a
//   displacement, a traction or ring forces; the interface's ring areas and the energies;
// - the push-out of a fibre from a matrix cylinder (config/pushout.cfg): the energy balance,
//   damage then friction dissipation, beta non-increasing, the load drop and a frictional
//   plateau that is mu times the interface's normal force; converging under refinement.
#include "helpers.hpp"
#include "rccm/app/simulation.hpp"
#include "rccm/fem/elasticity.hpp"
#include "rccm/model/body_state.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <unistd.h>

using namespace rccm;
namespace fs = std::filesystem;

namespace {

const std::string meshes = std::string(RCCM_SOURCE_DIR) + "/tests/meshes/axisymmetric/";

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Runs a config (no files) and returns the bulk at the last accepted step, on `model` (built
/// from the same config).
BodyState final_body(const Config& cfg, const Model& model, InterfaceState* last = nullptr, RunResult* result = nullptr) {
  BodyState out;
  RunOptions o;
  o.observer = [&](const AcceptedStep& a) {
    out = body_state(model, a.state);
    if (last) *last = a.state;
  };
  const RunResult r = Simulation(cfg, o).run();
  REQUIRE(r.stopped.empty());
  if (result) *result = r;
  return out;
}

// ---------------------------------------------------------------------------------------
// Lame: u_r = A r + B / r, u_z = 0 (plane strain along z), so eps_rr = A - B/r^2,
// eps_thth = A + B/r^2, eps_zz = 0 and, with lambda and mu Lame's constants,
//   sigma_rr = 2 (lambda + mu) A - 2 mu B / r^2,  sigma_thth = 2 (lambda + mu) A + 2 mu B / r^2,
//   sigma_zz = 2 lambda A.
// Boundary conditions: sigma_rr(a) = -p (the pressure pushes into the wall) and either
// u_r(b) = 0 (k < 0: a rigid wall, Signorini with contact closed) or the bonded spring of the
// interface, sigma_rr(b) = -k u_r(b) (k = Cn; valid while u_r(b) <= 0, the bond in tension).
struct Lame {
  double A = 0, B = 0, lambda = 0, mu = 0;
  Lame(double E, double nu, double a, double b, double p, double k) {
    lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
    mu = E / (2 * (1 + nu));
    // [m11 m12; m21 m22] [A; B] = [-p; 0]
    const double m11 = 2 * (lambda + mu), m12 = -2 * mu / (a * a);
    const double m21 = k < 0 ? b : 2 * (lambda + mu) + k * b, m22 = k < 0 ? 1 / b : -2 * mu / (b * b) + k / b;
    const double det = m11 * m22 - m12 * m21;
    A = -p * m22 / det;
    B = p * m21 / det;
  }
  double u(double r) const { return A * r + B / r; }
  double srr(double r) const { return 2 * (lambda + mu) * A - 2 * mu * B / (r * r); }
  double stt(double r) const { return 2 * (lambda + mu) * A + 2 * mu * B / (r * r); }
  double szz() const { return 2 * lambda * A; }
};

struct LameErrors {
  double h = 0;
  double u = 0;       // max |u_r - u_exact| over the nodes / max |u_exact|
  double uz = 0;      // max |u_z| / max |u_exact|
  double stress = 0;  // relative L2 (2 pi r dA) of (sigma_rr, sigma_thth, sigma_zz) at the cell centres
  double ub = 0;      // u_r at r = b (mean over the outer nodes), and its closed form
  double ub_exact = 0;
  double scale = 0;   // max |u_exact|
  double pressure_force = 0, pressure_force_exact = 0;  // resultant of the pressure load (inward), N
};

/// The cylinder a = 1 < r < b = 2, a slice of h = 0.25 (u_z = 0 on both ends), E = 1000,
/// nu = 0.3, p inside; its outer surface bonded (Cn = Ct = k) to the rigid wall x = b.
LameErrors lame_fe(int refine, bool quads, double p, double k) {
  const double a = 1, b = 2, h = 0.25, E = 1000, nu = 0.3;
  std::ostringstream text;
  text << std::setprecision(17) << "mesh = { file = \"" << meshes << "annulus.geo\"; refine = " << refine
       << "; parameters = { quads = " << (quads ? 1 : 0) << "; }; };\n"
       << "material = { E = " << E << "; nu = " << nu << "; hypothesis = \"axisymmetric\"; };\n"
       << "interface = { boundary = \"outer\"; normal = [-1.0, 0.0]; Cn = " << k << "; Ct = " << k
       << "; w = 1.0; alpha = 1.0; mu = 0.3; };\n"
       << R"(loads = ( { node_set = "bottom"; type = "displacement"; component = "y"; value = 0.0; },
          { node_set = "top"; type = "displacement"; component = "y"; value = 0.0; },
          { node_set = "inner"; type = "pressure"; value = )"
       << p << R"(; } );
time = { T = 1.0; steps = 1; };
integrator = { method = "contact-only"; };
)";
  const Config cfg = test::config_from_text(text.str());
  const Model model = test::make_model(cfg);
  const BodyState body = final_body(cfg, model);
  // Against the wall with contact closed, the exact solution has u_r(b) = 0 whatever Cn.
  const Lame exact(E, nu, a, b, p, p > 0 ? -1.0 : k);
  const Mesh& mesh = model.mesh();
  LameErrors e;
  const double scale = e.scale = std::max(std::abs(exact.u(a)), std::abs(exact.u(b)));
  int outer = 0;
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    const double r = mesh.nodes[n].x();
    e.u = std::max(e.u, std::abs(body.u[mesh.dof(n, 0)] - exact.u(r)) / scale);
    e.uz = std::max(e.uz, std::abs(body.u[mesh.dof(n, 1)]) / scale);
    if (std::abs(r - b) < 1e-12) e.ub += body.u[mesh.dof(n, 0)], ++outer;
  }
  e.ub /= outer;
  e.ub_exact = exact.u(b);
  const CellFields f = cell_fields(mesh, model.materials(), body.u);
  double num = 0, den = 0;
  e.h = 0;
  for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (int n : mesh.cells[c]) centre += mesh.nodes[n];
    centre /= double(mesh.cells[c].size());
    double area = 0;  // shoelace
    for (std::size_t j = 0; j < mesh.cells[c].size(); ++j) {
      const Eigen::Vector3d &P = mesh.nodes[mesh.cells[c][j]], &Q = mesh.nodes[mesh.cells[c][(j + 1) % mesh.cells[c].size()]];
      area += 0.5 * (P.x() * Q.y() - Q.x() * P.y());
      e.h = std::max(e.h, (P - Q).norm());
    }
    const double r = centre.x(), dV = 2 * M_PI * r * area;
    // Voigt (xx, yy, xy, zz) = (rr, zz, rz, thth) on a meridian section.
    const double drr = f.stress(0, c) - exact.srr(r), dtt = f.stress(3, c) - exact.stt(r), dzz = f.stress(1, c) - exact.szz();
    num += dV * (drr * drr + dtt * dtt + dzz * dzz + 2 * f.stress(2, c) * f.stress(2, c));
    den += dV * (exact.srr(r) * exact.srr(r) + exact.stt(r) * exact.stt(r) + exact.szz() * exact.szz());
  }
  e.stress = std::sqrt(num / den);
  e.pressure_force = body.force[2];
  e.pressure_force_exact = p * 2 * M_PI * a * h;
  return e;
}

}  // namespace

TEST_CASE("Lame's thick cylinder, axisymmetric: u_r and the stresses converge to the closed form, the bond is "
          "the Robin condition sigma_rr(b) = -Cn u_r(b), the closed contact u_r(b) = 0",
          "[axisymmetric]") {
  const auto start = std::chrono::steady_clock::now();
  // p = -1: suction, the cylinder shrinks and its bond (Cn = 500 MPa/mm, Cn b / E = 1: it
  // matters) holds it in tension. p = +1: it swells against the wall, contact closes.
  for (double p : {-1.0, 1.0})
    for (bool quads : {true, false}) {
      std::cout << "Lame, p = " << p << (quads ? ", Q4" : ", T3")
                << ": h, max nodal |u_r error|/max|u|, order, L2 stress error, order, u_r(b) FE / exact\n";
      std::vector<LameErrors> levels;
      for (int refine = 0; refine <= 3; ++refine) {
        levels.push_back(lame_fe(refine, quads, p, 500.0));
        const LameErrors& e = levels.back();
        const bool coarser = levels.size() > 1;
        const double order_u = coarser ? std::log2(levels[levels.size() - 2].u / e.u) : 0.0;
        const double order_s = coarser ? std::log2(levels[levels.size() - 2].stress / e.stress) : 0.0;
        std::cout << "  " << e.h << "  " << e.u << "  " << order_u << "  " << e.stress << "  " << order_s << "  " << e.ub
                  << " / " << e.ub_exact << "\n";
        INFO("p = " << p << (quads ? " Q4" : " T3") << ", refine " << refine << ": u error " << e.u << ", stress error "
                    << e.stress << ", u_z " << e.uz);
        // The pressure's resultant is p times the inner ring area, to round-off.
        CHECK(e.pressure_force == Approx(e.pressure_force_exact).epsilon(1e-12));
        if (p > 0) CHECK(std::abs(e.ub) < 1e-8 * e.scale);  // closed contact: no penetration
        if (quads) {
          // The Q4 mesh is mirror symmetric in z: u_z = 0 as in the closed form, the nodal
          // displacement and the centre stresses converge at second order.
          CHECK(e.uz < 1e-9);
          if (coarser) CHECK(order_u > 1.9);
          if (coarser) CHECK(order_s > 1.9);
        } else if (coarser) {
          // T3 (each quad cut along one diagonal) is not: a spurious u_z that vanishes under
          // refinement (none on the coarsest mesh, one row of cells held at both ends), and
          // orders that reach 2 (u) and 1 (stress) from below.
          if (refine >= 2) CHECK(e.uz < 0.6 * levels[levels.size() - 2].uz);
          CHECK(order_u > 1.2);
          CHECK(order_s > 0.55);
        }
      }
      CHECK(levels.back().u < (quads ? 2e-4 : 1.5e-3));
      CHECK(levels.back().stress < (quads ? 2e-4 : 1.5e-2));
      if (!quads) CHECK(levels.back().uz < 2e-4);
      // The bond's displacement: the Robin closed form (p < 0), 0 by contact (p > 0).
      if (p < 0) CHECK(levels.back().ub == Approx(levels.back().ub_exact).epsilon(1e-3));
    }
  std::cout << "Lame: " << seconds_since(start) << " s\n";
}

namespace {

// ---------------------------------------------------------------------------------------
// Shear lag. A fibre 0 < r < a, 0 < z < L (E, G = E / 2 (1 + nu), nu = 0) bonded along r = a
// to a rigid matrix by the tangential spring Ct; its end z = L displaced by delta, z = 0
// free. With N = E pi a^2 u' the axial force and u the mean axial displacement over the
// section, the equilibrium of a slice dz is dN/dz = 2 pi a tau, tau = Ct u_s the bond's
// shear stress at the fibre's surface displacement u_s:
//   E pi a^2 u'' = 2 pi a Ct u_s.
// Plain shear lag takes u_s = u (the section stays plane): u = delta cosh(lambda z) /
// cosh(lambda L), lambda^2 = 2 Ct / (E a), and the end stiffness
//   K = N(L) / delta = pi a^2 E lambda tanh(lambda L).
// The section does not stay plane: the axial stress gradient s = sigma_zz' is uniform over
// it, so equilibrium (1/r) (r tau_rz)' = -s gives tau_rz = -s r / 2 and u_z' = tau_rz / G:
// u_z(r) = u_z(0) - s r^2 / (4 G); the surface lags the mean by s a^2 / (8 G) = Ct u_s a /
// (4 G). Hence u_s = u / (1 + Ct a / (4 G)): the same equation with the interface and a
// quarter radius of fibre in series, 1/Ct_eff = 1/Ct + a / (4 G). Plain shear lag is off by
// the relative amount d ln K / d ln Ct * (Ct a / 4 G) ~ Ct a / (8 G) (lambda L large): it
// holds for Ct a / G << 1 (a slender fibre, lambda a = sqrt(2 Ct a / E) << 1); with Ct_eff
// what is left is the ends, where the section is not yet parabolic over about a radius
// (a share ~ lambda a of the load transfer): O((Ct a / G) lambda a) = O((Ct a / G)^(3/2))
// at nu = 0, where (lambda a)^2 = Ct a / G. nu = 0 also keeps the radial spring Cn out of
// the axial problem (no Poisson contraction for it to resist).
double shear_lag_stiffness(double E, double a, double L, double Ct) {
  const double lambda = std::sqrt(2 * Ct / (E * a));
  return M_PI * a * a * E * lambda * std::tanh(lambda * L);
}

struct ShearLag {
  double eps = 0;          // Ct a / G
  double stiffness = 0;    // FE: reaction at the pulled end / delta, N/mm
  double plain = 0, series = 0;  // the closed forms with Ct and Ct_eff
  double profile = 0;      // max over the surface nodes 2 a from the ends |u_s - u_s exact| / delta (Ct_eff)
  double beta_min = 1;
  double ring_area = 0, ring_area_exact = 0;     // sum of the pairs' measures a_i, and 2 pi a L
  double work = 0, work_exact = 0, imbalance = 0;  // external work, 1/2 K delta^2, relative imbalance
  double free_energy = 0, free_energy_exact = 0; // the bond's elastic energy, FE and closed form (Ct_eff)
};

enum class Pull { Displacement, Traction, RingForces };

/// The fibre a = 1, E = 1000, nu = 0 with lambda_eff L = 2.5, 8 cells across the radius
/// and per unit length, pulled over T = 1 s by the displacement delta = 0.01 of its end face,
/// or by the force K_series delta that should move it by delta as far as the closed form
/// goes: a uniform traction, or 9 equal ring forces on the end face's 9 nodes (a "force" load
/// is the force on the whole ring). ARKODE: beta must stay 1.
ShearLag shear_lag_fe(double Ct, Pull pull = Pull::Displacement) {
  const double a = 1, E = 1000, G = E / 2, delta = 0.01;
  const double Ct_eff = 1 / (1 / Ct + a / (4 * G)), lambda = std::sqrt(2 * Ct_eff / (E * a)), L = 2.5 / lambda;
  const int nz = static_cast<int>(std::lround(8 * L));
  const double force = shear_lag_stiffness(E, a, L, Ct_eff) * delta;
  std::ostringstream load;
  load << std::setprecision(17) << "loads = ( { node_set = \"top\"; component = \"y\"; ";
  if (pull == Pull::Displacement) load << "type = \"displacement\"; value = " << delta;
  if (pull == Pull::Traction) load << "type = \"traction\"; value = " << force / (M_PI * a * a);
  if (pull == Pull::RingForces) load << "type = \"force\"; value = " << force / 9;
  load << "; } );\n";
  std::ostringstream text;
  text << std::setprecision(17) << "mesh = { file = \"" << meshes << "rod.geo\"; parameters = { a = " << a
       << "; L = " << L << "; nr = 8; nz = " << nz << "; }; };\n"
       << "material = { E = " << E << "; nu = 0.0; hypothesis = \"axisymmetric\"; };\n"
       << "interface = { boundary = \"surface\"; normal = [-1.0, 0.0]; Cn = " << Ct << "; Ct = " << Ct
       << "; w = 1.0; alpha = 1.0; mu = 0.3; };\n"
       << load.str()
       << "time = { T = 1.0; };\n";
  const Config cfg = test::config_from_text(text.str());
  const Model model = test::make_model(cfg);
  InterfaceState last;
  RunResult result;
  const BodyState body = final_body(cfg, model, &last, &result);
  ShearLag s;
  s.eps = Ct * a / G;
  s.stiffness = body.force[0] / delta;
  s.plain = shear_lag_stiffness(E, a, L, Ct);
  s.series = shear_lag_stiffness(E, a, L, Ct_eff);
  s.beta_min = last.beta.minCoeff();
  for (const ContactPair& c : model.interface().pairs) s.ring_area += c.measure;
  s.ring_area_exact = 2 * M_PI * a * L;
  // Energies: the pull is a ramp and the response linear, so the work is 1/2 K delta^2; the
  // bond stores int 1/2 Ct u_s^2 2 pi a dz, with u_s = delta cosh(lambda z) / (cosh(lambda L)
  // (1 + Ct a / 4 G)) and int_0^L cosh^2 = L / 2 + sinh(2 lambda L) / (4 lambda).
  s.work = result.energy.external_work;
  s.work_exact = 0.5 * body.force[0] * delta;
  s.imbalance = result.energy.relative_error();
  s.free_energy = result.energy.free_energy_change;
  const double us_L = delta / (std::cosh(lambda * L) * (1 + Ct * a / (4 * G)));
  s.free_energy_exact = M_PI * a * Ct * us_L * us_L * (L / 2 + std::sinh(2 * lambda * L) / (4 * lambda));
  // The surface's axial displacement u_s(z) = delta cosh(lambda z) / cosh(lambda L) / (1 + Ct a / 4 G)
  // away from the ends, where the section is not parabolic (a boundary layer of about a
  // radius): the grip holds it at delta, the free end has sigma_zz = 0.
  const Mesh& mesh = model.mesh();
  for (const ContactPair& c : model.interface().pairs) {
    const double z = mesh.nodes[c.node].y();
    if (z < 2 * a || z > L - (pull == Pull::Displacement ? 2 : 4) * a) continue;
    const double exact = delta * std::cosh(lambda * z) / std::cosh(lambda * L) / (1 + Ct * a / (4 * G));
    s.profile = std::max(s.profile, std::abs(body.u[mesh.dof(c.node, 1)] - exact) / delta);
  }
  return s;
}

}  // namespace

TEST_CASE("shear lag: a fibre bonded to a rigid matrix carries its load as E a^2 u'' = 2 a Ct u, to the fibre's "
          "own shear compliance",
          "[axisymmetric]") {
  const auto start = std::chrono::steady_clock::now();
  std::cout << "shear lag: Ct a/G, K_FE [N/mm], K plain, K series, K_FE/K_plain - 1, K_FE/K_series - 1, "
               "profile error/delta\n";
  std::vector<ShearLag> runs;
  for (double Ct : {5.0, 20.0, 80.0}) {
    runs.push_back(shear_lag_fe(Ct));
    const ShearLag& s = runs.back();
    const double plain = s.stiffness / s.plain - 1, series = s.stiffness / s.series - 1;
    std::cout << "  " << s.eps << "  " << s.stiffness << "  " << s.plain << "  " << s.series << "  " << plain << "  "
              << series << "  " << s.profile << "; bond energy " << s.free_energy << " (closed form "
              << s.free_energy_exact << "), work " << s.work << " (1/2 F delta " << s.work_exact << "), imbalance "
              << s.imbalance << "\n";
    INFO("Ct a/G = " << s.eps << ": K " << s.stiffness << ", plain " << s.plain << " (" << plain << "), series "
                     << s.series << " (" << series << "), profile " << s.profile);
    CHECK(s.beta_min == 1.0);  // elastic: the bond never damages (w = 1 >> Ct u^2)
    // Plain shear lag overestimates the stiffness by the fibre's shear compliance, ~ Ct a / (8 G).
    CHECK(plain < 0);
    CHECK(-plain == Approx(s.eps / 8).epsilon(0.25));
    // With the series compliance what is left is the boundary layers at the ends (a radius
    // long, where the section is not yet parabolic), O((Ct a / G)^(3/2)), and the mesh's 1e-4.
    CHECK(std::abs(series) < 0.1 * std::pow(s.eps, 1.5) + 1e-4);
    CHECK(std::abs(series) < 0.3 * std::abs(plain));
    CHECK(s.profile < 0.1 * std::pow(s.eps, 1.5) + 5e-5);
    // The interface's measures are ring areas, 2 pi a dz; the energies those of the whole ring.
    CHECK(s.ring_area == Approx(s.ring_area_exact).epsilon(1e-12));
    CHECK(s.work == Approx(s.work_exact).epsilon(1e-9));
    CHECK(s.imbalance < 1e-9);
    CHECK(s.free_energy == Approx(s.free_energy_exact).epsilon(0.3 * std::pow(s.eps, 1.5) + 1e-4));
  }
  // Force control (Ct a / G = 0.04), 4 radii from the end (Saint-Venant): a uniform traction
  // moves the fibre as the displacement delta does; 9 equal ring forces on the end face (a
  // stress ~ 1/r, concentrated at the axis) leave the surface near the end behind, transfer
  // less there and move the rest 0.5 % more: the force is the ring's, not per radian or per
  // unit length of circumference (a factor 2 pi r).
  const ShearLag traction = shear_lag_fe(20.0, Pull::Traction), rings = shear_lag_fe(20.0, Pull::RingForces);
  std::cout << "  force control, Ct a/G = 0.04: profile error/delta " << traction.profile << " (traction), "
            << rings.profile << " (9 ring forces); imbalance " << traction.imbalance << ", " << rings.imbalance << "\n";
  CHECK(traction.profile < 0.1 * std::pow(traction.eps, 1.5) + 5e-5);
  CHECK(rings.profile < 1e-2);
  CHECK(traction.imbalance < 1e-9);
  CHECK(rings.imbalance < 1e-9);
  std::cout << "shear lag: " << seconds_since(start) << " s\n";
}

namespace {

struct PushOut {
  RunResult result;
  test::CsvTable curves;
  double beta_increase = 0;   // largest increase of any beta between accepted steps
  double beta_max_end = 0;    // largest beta at T
  int sliding_end = 0, pairs = 0;
  // At T: the interface's axial force on the fibre (Rbar_t + Radh_t), its friction part, and
  // what Coulomb's law gives for it while every node slides, sum mu (1 - beta_i) Rbar_n,i.
  double sum_r_t = 0, sum_Rbar_t = 0, coulomb = 0, sum_Rbar_n = 0;
  // At T: the largest |u_r| of a node on the axis (held at 0) and of any fibre node.
  double axis_ur = -1, fibre_ur = 0;
};

PushOut run_pushout(std::vector<std::string> overrides) {
  const fs::path dir = fs::temp_directory_path() / ("rccm_pushout_" + std::to_string(::getpid()));
  overrides.push_back("output.directory=\"" + dir.string() + "\"");
  const Config cfg = load_config(test::shipped("pushout.cfg"), overrides);
  const Model model = test::make_model(cfg);
  const double mu = cfg.interfaces.front().mu;
  PushOut p;
  Eigen::VectorXd previous;
  RunOptions o;
  o.write_files = true;
  o.force = true;
  o.observer = [&](const AcceptedStep& a) {
    if (previous.size() > 0) p.beta_increase = std::max(p.beta_increase, (a.state.beta - previous).maxCoeff());
    previous = a.state.beta;
    p.beta_max_end = a.state.beta.maxCoeff();
    p.pairs = static_cast<int>(a.state.beta.size());
    p.sliding_end = static_cast<int>(std::count(a.state.status.begin(), a.state.status.end(), Status::Slide));
    const Eigen::VectorXd Radh = adhesive_forces(model, a.state);
    p.sum_r_t = p.sum_Rbar_t = p.coulomb = p.sum_Rbar_n = 0;
    for (int i = 0; i < p.pairs; ++i) {
      p.sum_Rbar_t += a.state.Rbar[2 * i];
      p.sum_r_t += a.state.Rbar[2 * i] + Radh[2 * i];
      p.sum_Rbar_n += a.state.Rbar[2 * i + 1];
      p.coulomb += mu * (1 - a.state.beta[i]) * a.state.Rbar[2 * i + 1];
    }
    if (a.t < cfg.time.T) return;
    const BodyState b = body_state(model, a.state);
    const Mesh& mesh = model.mesh();
    p.axis_ur = 0;
    for (int n = 0; n < mesh.num_nodes(); ++n) {
      if (mesh.nodes[n].x() == 0.0) p.axis_ur = std::max(p.axis_ur, std::abs(b.u[mesh.dof(n, 0)]));
      if (mesh.nodes[n].x() <= 0.07) p.fibre_ur = std::max(p.fibre_ur, std::abs(b.u[mesh.dof(n, 0)]));
    }
  };
  p.result = Simulation(cfg, o).run();
  p.curves = test::read_csv((dir / "curves.csv").string());
  fs::remove_all(dir);
  return p;
}

}  // namespace

TEST_CASE("push-out of a fibre (config/pushout.cfg): the energy balance closes, damage then friction dissipate, "
          "the load drops to a frictional plateau mu sum Rbar_n",
          "[axisymmetric]") {
  const auto start = std::chrono::steady_clock::now();
  const PushOut p = run_pushout({});
  const RunResult& r = p.result;
  REQUIRE(r.stopped.empty());
  const EnergyTerms& e = r.energy;
  const std::vector<double> t = p.curves.numbers("t [s]"), F = p.curves.numbers("L2 fibre_top.y force [N]"),
                            damage = p.curves.numbers("damage dissipation [N mm]"),
                            friction = p.curves.numbers("friction dissipation [N mm]");
  // The push: the peak force, the force at T (the plateau) and the drop between.
  std::size_t peak = 0;
  for (std::size_t k = 0; k < F.size(); ++k)
    if (std::abs(F[k]) > std::abs(F[peak])) peak = k;
  const double plateau = std::abs(F.back());
  // The plateau is flat: the force over the last 30 % of the push changes by little.
  double lo = plateau, hi = plateau;
  for (std::size_t k = 0; k < t.size(); ++k)
    if (t[k] >= 0.7) lo = std::min(lo, std::abs(F[k])), hi = std::max(hi, std::abs(F[k]));
  // When did each dissipation start (first step above 1e-6 of its final value)?
  const auto onset = [&](const std::vector<double>& v) {
    for (std::size_t k = 0; k < v.size(); ++k)
      if (v[k] > 1e-6 * v.back()) return t[k];
    return t.back();
  };
  std::cout << "push-out: peak " << std::abs(F[peak]) << " N at t = " << t[peak] << " s, plateau " << plateau
            << " N (" << lo << " .. " << hi << " over t >= 0.7 s), sum r_t " << p.sum_r_t << " N, sum Rbar_t "
            << p.sum_Rbar_t << " N, sum mu (1 - beta) Rbar_n " << p.coulomb << " N, sum Rbar_n " << p.sum_Rbar_n
            << " N; external work " << e.external_work << ", strain "
            << e.strain_energy << ", free energy change " << e.free_energy_change << ", damage "
            << e.damage_dissipation << ", friction " << e.friction_dissipation << " N mm, relative imbalance "
            << e.relative_error() << "; damage from t = " << onset(damage) << ", friction from t = " << onset(friction)
            << "; " << r.steps.size() << " steps, " << seconds_since(start) << " s\n";
  INFO("relative imbalance " << e.relative_error() << ", damage " << e.damage_dissipation << ", friction "
                             << e.friction_dissipation);
  CHECK(e.relative_error() < 1e-5);
  CHECK(e.damage_dissipation > 0.1 * e.external_work);
  CHECK(e.friction_dissipation > 0.1 * e.external_work);
  // Debonding comes first: friction needs mubar = mu (1 - beta) > 0.
  CHECK(onset(damage) <= onset(friction));
  for (const auto* v : {&damage, &friction}) {
    double worst = 0;
    for (std::size_t k = 1; k < v->size(); ++k) worst = std::min(worst, (*v)[k] - (*v)[k - 1]);
    CHECK(worst >= -1e-9 * v->back());
  }
  CHECK(p.beta_increase <= 0.0);  // beta never increases
  // u_r = 0 on the axis, imposed (the fibre, pressed and pushed, moves radially elsewhere).
  CHECK(p.axis_ur == 0.0);
  CHECK(p.fibre_ur > 1e-6);  // 4.7e-6 mm
  // Fully debonded and sliding at T: the load is carried by friction alone. The fibre's
  // bottom is free, so the push balances the interface's axial forces, each mu Rbar_n.
  CHECK(p.beta_max_end < 1e-2);
  CHECK(p.sliding_end == p.pairs);
  CHECK(std::abs(p.sum_Rbar_t) == Approx(p.coulomb).epsilon(1e-8));  // on the cone at every node
  CHECK(plateau == Approx(std::abs(p.sum_r_t)).epsilon(1e-8));       // the fibre's equilibrium
  CHECK(std::abs(p.sum_Rbar_t) > 0.999 * std::abs(p.sum_r_t));       // friction carries it, not the spring
  // The load drop: the peak is several times the plateau, reached before T, then flat.
  CHECK(std::abs(F[peak]) > 3 * plateau);
  CHECK(t[peak] < 0.7);
  CHECK(hi - lo < 0.01 * plateau);
}

TEST_CASE("push-out under uniform refinement: the peak force, the plateau and the dissipations converge",
          "[axisymmetric]") {
  // The shipped mesh (fibre 4 x 20, matrix 8 x 20 cells) split once and twice.
  const auto start = std::chrono::steady_clock::now();
  struct Level {
    double peak = 0, plateau = 0, damage = 0, friction = 0;
  };
  std::vector<Level> levels;
  std::cout << "push-out refinement: refine, contact nodes, peak force [N], plateau [N], damage, friction [N mm]\n";
  for (int refine = 0; refine <= 2; ++refine) {
    const PushOut p = run_pushout({"mesh.refine=" + std::to_string(refine)});
    REQUIRE(p.result.stopped.empty());
    const std::vector<double> F = p.curves.numbers("L2 fibre_top.y force [N]");
    Level l;
    for (double f : F) l.peak = std::max(l.peak, std::abs(f));
    l.plateau = std::abs(F.back());
    l.damage = p.result.energy.damage_dissipation;
    l.friction = p.result.energy.friction_dissipation;
    levels.push_back(l);
    std::cout << "  " << refine << "  " << p.pairs << "  " << l.peak << "  " << l.plateau << "  " << l.damage << "  "
              << l.friction << "\n";
    INFO("refine " << refine);
    CHECK(p.sliding_end == p.pairs);
    CHECK(std::abs(p.sum_Rbar_t) == Approx(p.coulomb).epsilon(1e-8));
    CHECK(p.result.energy.relative_error() < 1e-5);
  }
  const auto shrinks = [&](double Level::*q, const char* what) {
    const double d1 = std::abs(levels[1].*q - levels[0].*q), d2 = std::abs(levels[2].*q - levels[1].*q);
    INFO(what << ": successive differences " << d1 << ", " << d2 << " (of " << levels[2].*q << ")");
    CHECK(d2 < 0.75 * d1);
    CHECK(d2 < 5e-3 * std::abs(levels[2].*q));
  };
  shrinks(&Level::peak, "peak");
  shrinks(&Level::plateau, "plateau");
  shrinks(&Level::damage, "damage dissipation");
  shrinks(&Level::friction, "friction dissipation");
  std::cout << "push-out refinement: " << seconds_since(start) << " s\n";
}

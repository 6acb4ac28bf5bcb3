// The FE body, the condensation and the contact solve against exact and direct solutions.
#include "helpers.hpp"
#include "rccm/base/errors.hpp"
#include "rccm/base/memory.hpp"
#include "rccm/contact/bipotential_solver.hpp"
#include "rccm/contact/newton_solver.hpp"
#include "rccm/contact/solver_tuning.hpp"
#include "rccm/fem/elasticity.hpp"
#include "rccm/model/body_state.hpp"
#include "rccm/model/interface_state.hpp"
#include "rccm/fem/loads.hpp"
#include "rccm/fem/mesh_source.hpp"
#include "rccm/interface/interface.hpp"
#include "rccm/model/model.hpp"

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <catch2/catch.hpp>

#include <cstdlib>
#include <random>

using namespace rccm;

namespace {

std::string block_config(const std::string& element, const std::string& interface_extra,
                         const std::string& loads) {
  return R"(
mesh = { size = [10.0, 5.0]; nx = 8; ny = 4; element = ")" + element + R"("; };
material = { E = 1000.0; nu = 0.3; };
interface = { boundary = "bottom"; Cn = 50.0; Ct = 30.0; w = 1.0e9; )" + interface_extra + R"( };
loads = ( )" + loads + R"( );
time = { T = 1.0; steps = 1; };
solver = { tolerance = 1.0e-12; };
)";
}

/// The contact solve at T = 1 s from the initial state.
ContactSolution solve_at_T(const Model& model, const SolverParams& p) {
  const InterfaceState s0 = InterfaceState::initial(model);
  BipotentialSolver solver(p);
  return solve_contact(model, solver, 1.0, s0.beta, s0);
}

}  // namespace

TEST_CASE("bonded interface equals a direct solve of K plus the interface springs", "[model]") {
  // beta uniform, no contact active (the loads open the interface everywhere, or the gap is
  // large), so the interface is the spring a_i beta^2 C alone: compare with K + springs
  // assembled here by hand and solved by Eigen's LDLT.
  const std::string loads =
      R"({ node_set = "top"; type = "traction"; component = "y"; value = 2.0; },
         { node_set = "right"; type = "traction"; component = "x"; value = -1.5; })";
  for (const std::string element : {"T3", "Q4"})
    for (double beta : {1.0, 0.6})
      for (double g0 : {0.0, 100.0}) {
        const std::string extra = "mu = 0.3; beta0 = " + std::to_string(beta) + "; g0 = " + std::to_string(g0) + ";";
        const Config cfg = test::config_from_text(block_config(element, extra, loads));
        const Model model = test::make_model(cfg);
        const ContactSolution s = solve_at_T(model, cfg.solver);
        REQUIRE(s.converged);
        const Eigen::VectorXd u = model.condensation().displacement(cfg.time.T, s.y);

        SparseMatrix K = model.stiffness();
        const double h = 10.0 / 8;
        const auto& bottom = model.mesh().node_set("bottom");
        for (std::size_t k = 0; k < bottom.size(); ++k) {
          const double a = (k == 0 || k + 1 == bottom.size()) ? h / 2 : h;
          K.coeffRef(2 * bottom[k], 2 * bottom[k]) += a * beta * beta * 30.0;
          K.coeffRef(2 * bottom[k] + 1, 2 * bottom[k] + 1) += a * beta * beta * 50.0;
        }
        Eigen::VectorXd f = Eigen::VectorXd::Zero(K.rows());
        const auto& top = model.mesh().node_set("top");
        for (std::size_t k = 0; k < top.size(); ++k)
          f[2 * top[k] + 1] = 2.0 * ((k == 0 || k + 1 == top.size()) ? h / 2 : h);
        const auto& right = model.mesh().node_set("right");
        for (std::size_t k = 0; k < right.size(); ++k)
          f[2 * right[k]] = -1.5 * ((k == 0 || k + 1 == right.size()) ? 5.0 / 8 : 5.0 / 4);
        Eigen::SimplicialLDLT<SparseMatrix> direct(K);
        const Eigen::VectorXd u_direct = direct.solve(f);
        INFO(element << " beta " << beta << " g0 " << g0);
        CHECK((u - u_direct).norm() <= 1e-10 * u_direct.norm());
        CHECK(s.Rbar.norm() <= 1e-10 * (1 + s.Radh(model.contact_problem(1, model.initial_beta(), s.u)).norm()));
      }
}

TEST_CASE("W0 from the Schur complement of the interface DOFs equals P K0^-1 P^T by direct solves", "[model]") {
  // The mesh rotated by 30 degrees, so that P mixes x and y, and the bottom-left contact
  // node held in x: its rows of P read a prescribed DOF, which must contribute nothing.
  const std::string loads =
      R"({ node_set = "bottom_left"; type = "displacement"; component = "x"; value = 0.0; },
         { node_set = "top"; type = "traction"; component = "y"; value = 2.0; })";
  const Config cfg = test::config_from_text(block_config("Q4", "mu = 0.3;", loads), {"mesh.rotation=30"});
  Model model = test::make_model(cfg);
  // K0's springs at beta = 1, then at a damaged beta (Model::condense: beta^2, at least the floor).
  Eigen::VectorXd beta = Eigen::VectorXd::Ones(model.contact_nodes());
  for (const bool damaged : {false, true}) {
  INFO((damaged ? "springs at a damaged beta" : "springs at beta = 1"));
  if (damaged) {
    for (int i = 0; i < beta.size(); ++i) beta[i] = i % 3 == 0 ? 0.0 : 1.0 / (1 + i);
    model.condense(beta);
  }
  CHECK(model.springs_beta() == beta);
  const Eigen::VectorXd w = beta.cwiseProduct(beta).cwiseMax(tuning::springs_floor);
  const SparseMatrix K0 = model.stiffness() + model.interface().springs(w, w);
  const std::vector<int> prescribed = prescribed_dofs(model.loads());
  REQUIRE(prescribed.size() == 1);
  std::vector<int> free;  // all DOFs but the prescribed one
  for (int d = 0; d < K0.rows(); ++d)
    if (d != prescribed[0]) free.push_back(d);
  const Eigen::MatrixXd K0d = K0;
  Eigen::MatrixXd K0_FF(free.size(), free.size()), P_F(model.interface().P.rows(), free.size());
  const Eigen::MatrixXd P = model.interface().P;
  for (std::size_t a = 0; a < free.size(); ++a) {
    P_F.col(a) = P.col(free[a]);
    for (std::size_t b = 0; b < free.size(); ++b) K0_FF(a, b) = K0d(free[a], free[b]);
  }
  const Eigen::MatrixXd W_direct = P_F * K0_FF.ldlt().solve(P_F.transpose());
  const Eigen::MatrixXd& W0 = *model.condensation().W0().dense();
  // Two factorizations of K0, whose condition number grows like 1 / springs_floor where the
  // floor springs alone hold the block.
  CHECK((W0 - W_direct).norm() <= (damaged ? 1e-13 / tuning::springs_floor : 1e-12) * W_direct.norm());
  CHECK(W0 == W0.transpose());
  CHECK(std::abs(P(0, prescribed[0])) > 0.1);  // contact node 0's t row does read the prescribed DOF
  // The contact problem's springs in K0 are these: E = Dref - D(beta) takes them back.
  const ContactProblem pb = model.contact_problem(1.0, beta, Eigen::VectorXd::Zero(P.rows()));
  const Eigen::VectorXd D1 = model.interface().spring_stiffness();
  for (int i = 0; i < beta.size(); ++i)
    for (int c = 2 * i; c < 2 * i + 2; ++c) CHECK(pb.Dref[c] == Approx(w[i] * D1[c]).epsilon(1e-14));
  }
}

namespace {

/// The loads' force at t = 1 (all DOFs).
Eigen::VectorXd loads_at_1(const Model& model) {
  Eigen::VectorXd F = Eigen::VectorXd::Zero(model.interface().P.cols());
  for (const LoadCase& lc : model.loads()) F += lc.amplitude(1.0) * lc.force;
  return F;
}

/// The model's condensation at springs(beta) against K0 = K + springs(beta) solved directly:
/// q0 at t = 1, W0's products with Y's columns and the body's displacement under them (and a
/// dense W0 itself, symmetric).
void check_against_direct_K0(const Model& model, const Eigen::VectorXd& beta, const Eigen::MatrixXd& Y) {
  const Eigen::MatrixXd P = model.interface().P;
  const Eigen::VectorXd F = loads_at_1(model);
  const Eigen::VectorXd w = beta.cwiseProduct(beta).cwiseMax(tuning::springs_floor);
  const Eigen::LDLT<Eigen::MatrixXd> direct(Eigen::MatrixXd(model.stiffness() + model.interface().springs(w, w)));
  const Eigen::MatrixXd W_direct = P * direct.solve(P.transpose());
  const Eigen::VectorXd q0_direct = P * direct.solve(F);
  const Condensation& c = model.condensation();
  CHECK((c.q0(1.0) - q0_direct).norm() <= 1e-10 * q0_direct.norm());
  if (const Eigen::MatrixXd* W0 = c.W0().dense()) {
    CHECK((*W0 - W_direct).norm() <= 1e-11 * W_direct.norm());
    CHECK(*W0 == W0->transpose());
  }
  for (int k = 0; k < Y.cols(); ++k) {
    Eigen::VectorXd Wy(P.rows());
    c.W0().multiply(Y.col(k), Wy);
    CHECK((Wy - W_direct * Y.col(k)).norm() <= 1e-10 * (W_direct * Y.col(k)).norm());
    const Eigen::VectorXd u = c.displacement(1.0, Y.col(k));
    const Eigen::VectorXd u_direct = direct.solve(P.transpose() * Y.col(k) + F);
    CHECK((u - u_direct).norm() <= 1e-10 * u_direct.norm());
  }
}

/// Random interface forces: `columns` of them, uniform in [-1, 1].
Eigen::MatrixXd random_forces(const Model& model, int columns, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> U(-1, 1);
  return Eigen::MatrixXd::NullaryExpr(model.interface().P.rows(), columns, [&]() { return U(gen); });
}

}  // namespace

TEST_CASE("condensations at damaged betas with W0 compressed: W0 q0 and the body equal direct solves of K0", "[model]") {
  // Model::condense on a compressed W0 (peeled from sparse solves): W0's products, q0 and the
  // body's displacement against K0 = K + springs(beta) solved directly, at beta = 1, at a
  // damaged beta and at one more damaged.
  const std::string loads = R"({ node_set = "top"; type = "traction"; component = "y"; value = 2.0; },
                               { node_set = "right"; type = "traction"; component = "x"; value = -1.0; })";
  const Config cfg = test::config_from_text(block_config("Q4", "mu = 0.3;", loads),
                                            {"mesh.nx=99", "solver.compressed_min_nodes=16"});
  Model model = test::make_model(cfg);
  const int n = model.contact_nodes();
  REQUIRE(n == 100);
  REQUIRE(model.condensation().W0().compressed() != nullptr);
  const Eigen::MatrixXd Y = random_forces(model, 4, 5);
  Eigen::VectorXd beta = Eigen::VectorXd::Ones(n);
  for (int stage = 0; stage < 3; ++stage) {
    if (stage == 1)
      for (int i = 0; i < n; ++i) beta[i] = i < 30 ? 0.0 : i < 60 ? 0.5 : 1.0;
    if (stage == 2)
      for (int i = 0; i < n; ++i) beta[i] = std::min(beta[i], i % 4 == 0 ? 0.2 : 0.9);
    if (stage > 0) model.condense(beta);
    INFO("stage " << stage);
    check_against_direct_K0(model, beta, Y);
  }
}

TEST_CASE("springs changed on a few pairs by Woodbury's formula: W0 q0 the body and its forms equal direct solves", "[model]") {
  // Model::condense when a few pairs' springs change: W0 and q0 follow by
  // Condensation::change_springs (K0 kept), the body's displacement and the body forms through
  // body_force; each against K0 with those springs solved directly. Dense and compressed W0,
  // springs lowered twice in a row, then raised back on some of the pairs.
  const std::string loads = R"({ node_set = "top"; type = "traction"; component = "y"; value = 2.0; },
                               { node_set = "right"; type = "traction"; component = "x"; value = -1.0; })";
  for (const bool compressed : {false, true}) {
    INFO((compressed ? "compressed W0" : "dense W0"));
    const Config cfg = test::config_from_text(
        block_config("Q4", "mu = 0.3;", loads),
        {"mesh.nx=99", std::string("solver.compressed_min_nodes=") + (compressed ? "16" : "1000")});
    Model model = test::make_model(cfg);
    const int n = model.contact_nodes();
    REQUIRE(n == 100);
    REQUIRE((model.condensation().W0().compressed() != nullptr) == compressed);
    const Condensation* const first = &model.condensation();
    const Eigen::MatrixXd Y = random_forces(model, 3, 7);
    Eigen::VectorXd beta = Eigen::VectorXd::Ones(n);
    for (int stage = 1; stage <= 3; ++stage) {
      INFO("stage " << stage);
      if (stage == 1) beta[10] = 0.0, beta[11] = 0.3, beta[50] = 0.5, beta[51] = 0.05;
      if (stage == 2) beta[11] = 0.0, beta[70] = 0.2, beta[99] = 0.6;
      if (stage == 3) beta[10] = 1.0, beta[70] = 0.9;  // stiffer again: dD < 0 on those
      model.condense(beta);
      REQUIRE(&model.condensation() == first);  // no new condensation: K0 kept
      CHECK(model.springs_beta() == beta);
      check_against_direct_K0(model, beta, Y);
      const Condensation& c = model.condensation();
      // The body forms (condensed with K0 at beta = 1) see the force of K0's splitting: the
      // probes-free resultants of a step equal those of the full displacement.
      InterfaceState s = InterfaceState::initial(model);
      s.t = 1.0, s.beta = beta, s.y = Y.col(0);
      c.W0().multiply(s.y, s.u);
      s.u += c.q0(1.0);
      const ContactProblem pb = model.contact_problem(1.0, beta, s.u);
      s.Rbar = s.y - (pb.Dref - pb.Dbeta).cwiseProduct(s.u);
      const BodyState full = body_state(model, s), forms = body_resultants(model, s);
      REQUIRE(full.force.size() == 2);
      for (std::size_t k = 0; k < full.force.size(); ++k) {
        CHECK(forms.force[k] == Approx(full.force[k]).epsilon(1e-9).margin(1e-12));
        CHECK(forms.displacement[k] == Approx(full.displacement[k]).epsilon(1e-9).margin(1e-12));
      }
      CHECK(forms.strain_energy == Approx(full.strain_energy).epsilon(1e-9));
      CHECK(c.body_force(1.0, s.y) != s.y);  // K0's springs differ from W0's on the changed pairs
    }
    // Springs changed on every pair: K0 factorized with them, the body takes y as it is.
    model.condense(Eigen::VectorXd::Constant(n, 0.5));
    CHECK(model.condensation().body_force(1.0, Y.col(0)) == Y.col(0));
  }
}

TEST_CASE("the springs follow beta on the pairs whose spring weighs more than twice its weight at beta", "[model]") {
  const std::string loads = R"({ node_set = "top"; type = "traction"; component = "y"; value = 1.0; })";
  Model model = test::make_model(test::config_from_text(block_config("Q4", "mu = 0.4;", loads),
                                                        {"solver.springs_follow_beta=true"}));
  const int n = model.contact_nodes();
  Eigen::VectorXd beta = Eigen::VectorXd::Ones(n);
  beta[0] = 0.0;   // weight 1e-2 (the floor) against 1: follows
  beta[1] = 0.7;   // 0.49: follows
  beta[2] = 0.71;  // 0.5041: more than half, stays
  beta[3] = 0.9;   // stays
  const Eigen::VectorXd s = model.springs_following(beta);
  CHECK(s[0] == 0.0);
  CHECK(s[1] == 0.7);
  CHECK(s[2] == 1.0);
  CHECK(s[3] == 1.0);
  for (int i = 4; i < n; ++i) CHECK(s[i] == 1.0);
  model.condense(s);
  beta[1] = 0.4;  // 0.16 against 0.49 in W0: follows again
  beta[0] = 0.0;
  const Eigen::VectorXd t = model.springs_following(beta);
  CHECK(t[1] == 0.4);
  CHECK(t[0] == 0.0);  // at the floor already
  CHECK(t[2] == 1.0);
}

TEST_CASE("the contact solution does not depend on the springs K0 holds (Model::condense)", "[model]") {
  // Only the splitting y = Rbar + E u changes with K0's springs: Rbar, u and the body's
  // displacement are the same for springs at beta = 1 and at any beta above the current one.
  const std::string loads = R"({ node_set = "top"; type = "displacement"; component = "x"; value = 0.005; },
                               { node_set = "top"; type = "displacement"; component = "y"; value = -0.02; })";
  for (const std::string element : {"T3", "Q4"}) {
    INFO(element);
    Model model = test::make_model(test::config_from_text(block_config(element, "mu = 0.4;", loads)));
    const int n = model.contact_nodes();
    Eigen::VectorXd beta(n), springs(n);
    for (int i = 0; i < n; ++i) beta[i] = i < n / 3 ? 0.0 : 0.3 + 0.7 * i / n, springs[i] = i % 2 ? beta[i] : 1.0;
    InterfaceState s0 = InterfaceState::initial(model);
    s0.beta = beta;
    BipotentialSolver solver(SolverParams{});
    const ContactSolution a = solve_contact(model, solver, 1.0, beta, s0);
    const Eigen::VectorXd u_a = model.condensation().displacement(1.0, a.y);
    model.condense(springs);
    solver.forget_W0();
    const ContactSolution b = solve_contact(model, solver, 1.0, beta, s0);
    const Eigen::VectorXd u_b = model.condensation().displacement(1.0, b.y);
    REQUIRE((a.converged && b.converged));
    CHECK((a.Rbar - b.Rbar).cwiseAbs().maxCoeff() <= 1e-8 * a.Rbar.cwiseAbs().maxCoeff());
    CHECK((a.u - b.u).cwiseAbs().maxCoeff() <= 1e-8 * a.u.cwiseAbs().maxCoeff());
    CHECK((u_a - u_b).cwiseAbs().maxCoeff() <= 1e-8 * u_a.cwiseAbs().maxCoeff());
    CHECK((a.y - b.y).cwiseAbs().maxCoeff() > 1e-3 * a.y.cwiseAbs().maxCoeff());  // another splitting indeed
    int sliding = 0, stuck = 0;
    for (Status st : a.status) sliding += st == Status::Slide, stuck += st == Status::Stick;
    CHECK((sliding > 0 && stuck > 0));  // both branches of the law take part
  }
}

TEST_CASE("K0's springs lag beta when 1 % of the pairs lost 10 times their stiffness in K0", "[model]") {
  const std::string loads = R"({ node_set = "top"; type = "traction"; component = "y"; value = 1.0; })";
  for (const bool follow : {true, false}) {
    Model model = test::make_model(test::config_from_text(
        block_config("Q4", "mu = 0.4;", loads), {"mesh.nx=149", std::string("solver.springs_follow_beta=") + (follow ? "true" : "false")}));
    const int n = model.contact_nodes();
    REQUIRE(n == 150);  // one lagging pair is 0.67 %, two are 1.3 %
    Eigen::VectorXd beta = Eigen::VectorXd::Ones(n);
    CHECK(!model.springs_lag(beta));
    beta[3] = 0.3;  // 0.09 of its spring in K0: lags
    CHECK(!model.springs_lag(beta));
    beta[5] = 0.32;  // 0.1024: not quite
    CHECK(!model.springs_lag(beta));
    beta[5] = 0.31;  // 0.0961
    CHECK(model.springs_lag(beta) == follow);
    if (!follow) continue;
    model.condense(beta);  // springs at 0.09 and 0.0961 of D(1) for pairs 3 and 5
    CHECK(!model.springs_lag(beta));
    // The floor (1e-2 of D(1)) is more than a tenth of their springs: they cannot lag again.
    beta[3] = beta[5] = 0.0;
    CHECK(!model.springs_lag(beta));
    beta[7] = beta[9] = 0.0;  // springs at beta = 1: down to the floor, they lag
    CHECK(model.springs_lag(beta));
  }
}

TEST_CASE("frictionless block pressed by a uniform pressure: uniform contact pressure", "[model]") {
  // Left edge on rollers (u_x = 0), top loaded by p: the exact stress is uniform,
  // sigma_yy = -p, so every contact node carries Rbar_n = p a_i.
  const double p = 10.0;
  for (const std::string element : {"T3", "Q4"}) {
    const std::string loads =
        R"({ node_set = "top"; type = "traction"; component = "y"; value = -10.0; },
           { node_set = "left"; type = "displacement"; component = "x"; value = 0.0; })";
    const Config cfg = test::config_from_text(block_config(element, "mu = 0.0; beta0 = 0.0;", loads));
    const Model model = test::make_model(cfg);
    const ContactSolution s = solve_at_T(model, cfg.solver);
    REQUIRE(s.converged);
    const Interface& I = model.interface();
    for (int i = 0; i < I.size(); ++i) {
      INFO(element << " node " << i);
      CHECK(s.Rbar[2 * i + 1] / I.pairs[i].measure == Approx(p).epsilon(1e-9));
      CHECK(std::abs(s.Rbar[2 * i]) <= 1e-9 * p);
      CHECK(std::abs(s.u[2 * i + 1]) <= 1e-12);
    }
  }
}

TEST_CASE("block pushed sideways under compression, beta = 0: Coulomb at every node", "[model]") {
  const double mu = 0.3, p = 10.0;
  for (const std::string element : {"T3", "Q4"}) {
    SECTION(element + ": above the threshold every node slides with |Rbar_t| = mu Rbar_n") {
      const std::string loads =
          R"({ node_set = "top"; type = "traction"; component = "y"; value = -10.0; },
             { node_set = "left"; type = "displacement"; component = "x"; value = 1.0; })";
      const Config cfg = test::config_from_text(block_config(element, "mu = 0.3; beta0 = 0.0;", loads));
      const Model model = test::make_model(cfg);
      const ContactSolution s = solve_at_T(model, cfg.solver);
      REQUIRE(s.converged);
      for (int i = 0; i < model.contact_nodes(); ++i) {
        INFO("node " << i);
        CHECK(s.status[i] == Status::Slide);
        CHECK(s.u[2 * i] > 0);                                            // slips along +x
        CHECK(s.Rbar[2 * i] == Approx(-mu * s.Rbar[2 * i + 1]).epsilon(1e-9));  // friction opposes it
      }
    }
    SECTION(element + ": below the threshold no node slips") {
      // A horizontal traction whose resultant is 5 % of mu times the normal load. nu = 0:
      // with nu > 0 the Poisson expansion under the pressure, resisted by friction, makes
      // the edge nodes slip whatever the push (real physics, not what this test is about).
      const double tx = 0.05 * mu * p * 10.0 / 5.0;
      const std::string loads = R"({ node_set = "top"; type = "traction"; component = "y"; value = -10.0; },
             { node_set = "left"; type = "traction"; component = "x"; value = )" + std::to_string(tx) + "; }";
      const Config cfg =
          test::config_from_text(block_config(element, "mu = 0.3; beta0 = 0.0;", loads), {"material.nu=0.0"});
      const Model model = test::make_model(cfg);
      const ContactSolution s = solve_at_T(model, cfg.solver);
      REQUIRE(s.converged);
      double sum_t = 0;
      for (int i = 0; i < model.contact_nodes(); ++i) {
        INFO("node " << i);
        CHECK(s.status[i] == Status::Stick);
        CHECK(std::abs(s.u[2 * i]) <= 1e-12);
        CHECK(std::abs(s.Rbar[2 * i]) < mu * s.Rbar[2 * i + 1]);
        sum_t += s.Rbar[2 * i];
      }
      CHECK(sum_t == Approx(-tx * 5.0).epsilon(1e-9));  // friction balances the push
    }
  }
}

TEST_CASE("a structure held by nothing is refused with a message", "[model]") {
  // Frictionless contact only, beta0 = 0, but the initial springs make K0 regular; a body
  // with no interface springs and no support cannot be built: a force-loaded block on an
  // interface of one node is free to rotate.
  const std::string text = R"(
mesh = { size = [10.0, 5.0]; nx = 2; ny = 2; node_sets = ( { name = "one"; box = [0.0, 0.0, 0.0, 0.0]; } ); };
material = { E = 1000.0; nu = 0.3; };
interface = { boundary = "one"; Cn = 50.0; Ct = 30.0; w = 1.0; mu = 0.0; };
loads = ( { node_set = "top"; type = "force"; component = "y"; value = -1.0; } );
time = { T = 1.0; };
)";
  const Config cfg = test::config_from_text(text);
  CHECK_THROWS_WITH(test::make_model(cfg), Catch::Contains("must be a chain of the mesh's boundary edges: node 0 at (0, 0) is on none of the set's own edges (a lone point"));
  const Config free_cfg = test::config_from_text(text, {"interface.boundary=\"bottom\"", "material.E=1e15", "interface.Cn=1e-9", "interface.Ct=1e-9"});
  CHECK_THROWS_WITH(test::make_model(free_cfg), Catch::Contains("not restrained"));
}

TEST_CASE("the interface notes a flat foundation tilted against its face, and pairs bonded across a gap", "[model]") {
  const std::string loads = R"({ node_set = "top"; type = "force"; component = "y"; value = 0.1; })";
  const auto notes = [&](const std::string& extra, std::vector<std::string> overrides = {}) {
    const Config cfg = test::config_from_text(block_config("Q4", "mu = 0.3; " + extra, loads), overrides);
    return make_interface(make_mesh(cfg), cfg).notes;
  };
  CHECK(notes("").empty());
  // The normal (0.3, 1) is 16.7 degrees off the face's (0, 1); (0.05, 1) 2.9, within 5.
  const std::vector<std::string> tilted = notes("normal = [0.3, 1.0];");
  REQUIRE(tilted.size() == 1);
  CHECK_THAT(tilted[0], Catch::Contains("interface.normal: (0.287348, 0.957826) is 16.7 degrees from the boundary's inward normal"));
  CHECK(notes("normal = [0.05, 1.0];").empty());
  // The mesh turned by 30 degrees: its normal must turn alike.
  CHECK(notes("", {"mesh.rotation=30"}).size() == 1);
  CHECK(notes("normal = [-0.5, 0.8660254037844386];", {"mesh.rotation=30"}).empty());
  // g0 > 0: noted for the bonded pairs only (a precracked or beta0 = 0 interface is open).
  const std::vector<std::string> gap = notes("g0 = 0.5;");
  REQUIRE(gap.size() == 1);
  CHECK_THAT(gap[0], Catch::Contains("9 contact node(s) start bonded across a gap, up to g0 = 0.5 mm"));
  CHECK(notes("g0 = 0.5; beta0 = 0.0;").empty());
  CHECK(notes("g0 = 0.0;").empty());
  // One gap per node: the largest named, where it is (node 6 of the bottom row, x = 7.5).
  const std::vector<std::string> one = notes("g0 = [0.0, 0.1, 0.0, 0.0, 0.0, 0.0, 0.9, 0.2, 0.0];");
  REQUIRE(one.size() == 1);
  CHECK_THAT(one[0], Catch::Contains("3 contact node(s) start bonded across a gap, up to g0 = 0.9 mm at mesh node 6 (7.5, 0)"));
  // A tilted face in unbonded contact (beta0 = 0) is contact of a curved or turned body: no note.
  CHECK(notes("normal = [0.3, 1.0]; beta0 = 0.0;").empty());
}

TEST_CASE("the compressed exact step gives the dense one's contact solution (B1, damaged, sliding)", "[model][compressed]") {
  // B1 on 128 x 4 cells (129 contact pairs, W0 258 x 258 in leaves of 64 rows), pressed on top
  // so that the far end sticks, beta damaged over the last quarter, solved with the exact
  // step's matrix and W0's products dense and compressed (HODLR), cold and then warm at a
  // later time with beta further damaged: the same Rbar and u to the solver's tolerance, and
  // separated, stick and slide pairs all present.
  const std::string text = R"(
mesh = { size = [50.0, 2.5]; nx = 128; ny = 4; element = "T3"; };
material = { E = 6.9e4; nu = 0.333; hypothesis = "plane_strain"; };
interface = { boundary = "bottom"; normal = [0.0, 1.0]; Cn = 2.0e5; Ct = 2.0e5; w = 1.0e-6; alpha = 1.0; mu = 0.2; beta0 = 1.0; };
loads = ( { node_set = "top_left"; type = "displacement"; component = "y"; value = 0.3; },
          { node_set = "top"; type = "traction"; component = "y"; value = -2.0; } );
time = { T = 10.0; steps = 210; };
solver = { tolerance = 1.0e-12; };
)";
  const Config dense_cfg = test::config_from_text(text, {"solver.compressed_min_nodes=100000"});
  const Config compressed_cfg = test::config_from_text(text, {"solver.compressed_min_nodes=0"});
  const Model model = test::make_model(dense_cfg);
  const Model compressed_model = test::make_model(compressed_cfg);
  REQUIRE(model.condensation().W0().compressed() == nullptr);
  REQUIRE(compressed_model.condensation().W0().compressed() != nullptr);
  {  // W0 compressed from sparse solves (the factor ordered freely) against W0 from the dense
     // factor block (the interface ordered last): its singular values fall to 1e-9 and below
     // within a few ranks
    const DelassusOperator& W0c = compressed_model.condensation().W0();
    REQUIRE(W0c.dense() == nullptr);
    const Eigen::MatrixXd& W0 = *model.condensation().W0().dense();
    for (int i : {0, 64, 128}) CHECK((W0c.block(2 * i, 2) - W0.block(2 * i, 2 * i, 2, 2)).norm() <= 1e-12 * W0.diagonal().maxCoeff());
    // The dense W0 compressed block by block: its blocks' singular values fall to 1e-9 of the
    // largest, where Eigen 3.4's BDCSVD lost 1e-6 of them (products 3e-8 off).
    const HodlrMatrix direct(W0, tuning::hodlr_accuracy * W0.diagonal().maxCoeff(), tuning::hodlr_leaf, 2);
    for (int k = 0; k < 4; ++k) {
      const Eigen::VectorXd y = k < 2 ? Eigen::VectorXd(Eigen::VectorXd::Unit(W0.rows(), 100 + 100 * k))
                                      : Eigen::VectorXd(Eigen::VectorXd::Random(W0.rows()));
      CHECK((direct.multiply(y) - W0 * y).norm() <= 1e-12 * (W0 * y).norm());
    }
    for (int k = 0; k < 4; ++k) {
      const Eigen::VectorXd y = k < 2 ? Eigen::VectorXd(Eigen::VectorXd::Unit(W0.rows(), 100 + 100 * k))
                                      : Eigen::VectorXd(Eigen::VectorXd::Random(W0.rows()));
      Eigen::VectorXd u(W0.rows());
      W0c.multiply(y, u);
      CHECK((u - W0 * y).norm() <= 1e-12 * (W0 * y).norm());
    }
  }
  const InterfaceState s0 = InterfaceState::initial(model);
  const auto damaged = [&](double front) {
    Eigen::VectorXd beta = model.initial_beta();
    for (int i = 0; i < model.contact_nodes(); ++i) beta[i] = std::min(1.0, std::max(0.0, 4.0 * (128 - i) / 128.0 - front));
    return beta;
  };
  BipotentialSolver dense(dense_cfg.solver), compressed(compressed_cfg.solver);
  const ContactSolution* previous_dense = nullptr;
  const ContactSolution* previous_compressed = nullptr;
  ContactSolution a, b;
  for (const auto& [t, front] : std::vector<std::pair<double, double>>{{5.0, 0.0}, {5.5, 0.4}}) {
    a = solve_contact(model, dense, t, damaged(front), s0, previous_dense);
    b = solve_contact(compressed_model, compressed, t, damaged(front), s0, previous_compressed);
    REQUIRE(a.converged);
    REQUIRE(b.converged);
    INFO("t = " << t);
    CHECK((b.Rbar - a.Rbar).norm() <= 1e-9 * a.y.norm());
    CHECK((b.u - a.u).norm() <= 1e-9 * a.u.norm());
    CHECK(std::count(a.status.begin(), a.status.end(), Status::Separated) > 0);
    CHECK(std::count(a.status.begin(), a.status.end(), Status::Stick) > 0);
    CHECK(std::count(a.status.begin(), a.status.end(), Status::Slide) > 0);
    CHECK(a.status == b.status);
    CHECK(b.iterations <= a.iterations + 2);  // the compressed exact step, not sweeps alone
    // The semi-smooth Newton solver on the compressed W0 (its 2D steps are the active-set system's).
    NewtonSolver newton(compressed_cfg.solver);
    const ContactSolution c = solve_contact(compressed_model, newton, t, damaged(front), s0, nullptr);
    REQUIRE(c.converged);
    CHECK((c.Rbar - a.Rbar).norm() <= 1e-9 * a.y.norm());
    CHECK(c.status == a.status);
    previous_dense = &a, previous_compressed = &b;
  }
}

TEST_CASE("a dense interface larger than the machine's memory is refused before assembly naming the setting", "[model]") {
  // B1 on 100 000 x 1 cells: m = 2 x 100 001 interface rows. Kept dense (compressed_min_nodes
  // above the node count), W0 and its factor block take 2 x 8 m^2 bytes = 640 GB; with the
  // exact step's three more matrices 5 x 8 m^2 = 1.6 TB.
  const double m = 2 * 100001.0;
  if (available_memory() > 5 * 8 * m * m) {
    WARN("this machine has " << available_memory() / 1e9 << " GB available: the refusal cannot be checked here");
    return;
  }
  const std::vector<std::string> dense = {"mesh.nx=100000", "mesh.ny=1", "solver.compressed_min_nodes=1000000"};
  std::vector<std::string> exact = dense;
  exact.push_back("solver.active_set_max_nodes=1000000");
  const auto refusal = [](const std::vector<std::string>& overrides) {
    const Config cfg = load_config(test::shipped("b1.cfg"), overrides);
    return Catch::Contains(cfg.where("interface.boundary") + ": 100001 contact nodes (dense interface operators)");
  };
  CHECK_THROWS_AS(test::make_model(load_config(test::shipped("b1.cfg"), dense)), InputError);
  CHECK_THROWS_WITH(test::make_model(load_config(test::shipped("b1.cfg"), dense)),
                    refusal(dense) && Catch::Contains("needs about 640 GB") &&
                        Catch::Contains("solver.compressed_min_nodes below the contact node count"));
  CHECK_THROWS_WITH(test::make_model(load_config(test::shipped("b1.cfg"), exact)),
                    refusal(exact) && Catch::Contains("needs about 1.6e+03 GB"));
}

namespace {
/// RCCM_MEMORY_GB set for a scope, unset after it (whatever the checks did).
struct MemoryCap {
  explicit MemoryCap(const char* gigabytes) { setenv("RCCM_MEMORY_GB", gigabytes, 1); }
  ~MemoryCap() { unsetenv("RCCM_MEMORY_GB"); }
};
}  // namespace

TEST_CASE("a body whose factor exceeds the memory rccm may take is refused once its ordering is known naming the mesh",
          "[model]") {
  // A 20 x 10 x 20 peel (14 553 unknowns): the mesh's up-front estimate (assembly_bytes, ~29
  // MB) fits in 50 MB, its Cholesky factor (~16 million entries, ~130 MB with CHOLMOD, ~84 MB
  // by MUMPS's own estimate) does not, and fits in 500 MB: refused between the two caps and
  // built above them, by either factorization.
  const std::string mesh = "mesh = { size = [20.0, 10.0, 20.0]; nx = 20; ny = 10; nz = 20; element = \"H8\"; };";
  for (const char* linear : {"\"cholmod\"", "\"mumps\""}) {
    const Config cfg = test::corner_peel(20, {std::string("solver.linear=") + linear}, mesh);
    INFO("solver.linear = " << linear);
    {
      const MemoryCap cap("0.05");
      CHECK(available_memory() <= 0.05e9);
      CHECK(assembly_bytes(3 * 21.0 * 11 * 21) < 0.05e9);  // the mesh's own check lets it through
      CHECK_THROWS_AS(test::make_model(cfg), InputError);
      CHECK_THROWS_WITH(test::make_model(cfg), Catch::StartsWith(cfg.where("mesh") + ": the Cholesky factor of the body's stiffness") &&
                                                   Catch::Contains("needs about 0.") && Catch::Contains("0.05 GB available") &&
                                                   Catch::Contains("use fewer cells"));
    }
    const MemoryCap cap("0.5");
    CHECK_NOTHROW(test::make_model(cfg));
  }
  // Not a number of gigabytes: said, not ignored.
  const MemoryCap bad("abc");
  CHECK_THROWS_WITH(available_memory(), "RCCM_MEMORY_GB=abc: must be a number of gigabytes > 0 (the memory rccm may plan with)");
}

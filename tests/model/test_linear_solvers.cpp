// The body's solves by PETSc (MUMPS, CG + GAMG) against CHOLMOD: the same displacements, the
// same W0 and free responses, from MUMPS's entries of K0^-1 on the interface and from its
// solves, in core and out of core; a floating body refused by each. One process here; the
// same under mpirun -np 2 is tests/check_mpi.py.
#include "helpers.hpp"
#include "rccm/fem/elastic_problem.hpp"
#include "rccm/la/petsc_solver.hpp"
#include "rccm/model/model.hpp"

#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <unistd.h>

using namespace rccm;

namespace {

// B1's layer on 64 x 4 cells, pressed and pulled (65 contact pairs).
const char* const kLayer = R"(
mesh = { size = [50.0, 2.5]; nx = 64; ny = 4; element = "T3"; };
material = { E = 6.9e4; nu = 0.333; hypothesis = "plane_strain"; };
interface = { boundary = "bottom"; normal = [0.0, 1.0]; Cn = 2.0e5; Ct = 2.0e5; w = 1.0e-6; alpha = 1.0; mu = 0.2; beta0 = 1.0; };
loads = ( { node_set = "top_left"; type = "displacement"; component = "y"; value = 0.3; },
          { node_set = "top"; type = "traction"; component = "y"; value = -2.0; } );
time = { T = 10.0; steps = 210; };
)";

LinearSolverParams solver(LinearSolver kind, double tolerance = 1e-12) { return {kind, tolerance}; }

double relative(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) { return (a - b).norm() / b.norm(); }

/// The DOFs P reads: the interface's.
std::vector<int> read_dofs(const SparseMatrix& P) {
  std::vector<int> dofs;
  for (int col = 0; col < P.outerSize(); ++col)
    if (SparseMatrix::InnerIterator(P, col)) dofs.push_back(col);
  return dofs;
}

/// MUMPS_OOC_TMPDIR set to `dir` while it lives.
struct OutOfCoreDirectory {
  explicit OutOfCoreDirectory(const std::string& dir) { setenv("MUMPS_OOC_TMPDIR", dir.c_str(), 1); }
  ~OutOfCoreDirectory() { unsetenv("MUMPS_OOC_TMPDIR"); }
};

}  // namespace

TEST_CASE("PETSc's MUMPS and CG + GAMG solve the body as CHOLMOD does", "[petsc]") {
  const Model model = test::make_model(test::config_from_text(kLayer));
  CHECK(model.linear_solver() == "CHOLMOD");  // auto in one process: the embedded default
  const Eigen::VectorXd one = Eigen::VectorXd::Ones(model.contact_nodes());
  const SparseMatrix springs = model.interface().springs(one, one);
  const ElasticProblem cholmod(model.stiffness(), springs, model.supports(), {}, solver(LinearSolver::Cholmod));
  const ElasticProblem mumps(model.stiffness(), springs, model.supports(), {}, solver(LinearSolver::Mumps));
  const ElasticProblem cg(model.stiffness(), springs, model.supports(), {}, solver(LinearSolver::CgGamg, 1e-10));
  const Eigen::Index n = model.stiffness().rows();
  Eigen::MatrixXd f = Eigen::MatrixXd::Random(n, 3), u_prescribed = Eigen::MatrixXd::Zero(n, 3);
  for (int d : model.supports()) u_prescribed.row(d).setConstant(0.01);  // also the K0_FD u_D term
  const Eigen::MatrixXd u = cholmod.solve(f, u_prescribed);
  CHECK(relative(mumps.solve(f, u_prescribed), u) <= 1e-11);
  // CG stops at 1e-10 of the residual; the error is at most cond(K0) times that.
  const Eigen::MatrixXd u_cg = cg.solve(f, u_prescribed);
  CHECK(relative(u_cg, u) <= 1e-5);
  CHECK(relative(u_cg, u) >= 1e-16);  // iterative: not the direct solution to the last bit
  // K u = f on the free DOFs (the prescribed rows carry the supports' reactions).
  const SparseMatrix K0 = model.stiffness() + springs;
  Eigen::MatrixXd r = K0 * u_cg - f;
  for (int d : model.supports()) r.row(d).setZero();
  CHECK(r.norm() <= 1e-8 * f.norm());
}

TEST_CASE("W0 and the free responses from MUMPS's solves equal those from CHOLMOD's factor", "[petsc]") {
  const Model cholmod = test::make_model(test::config_from_text(kLayer, {"solver.linear=\"cholmod\""}));
  const Model mumps = test::make_model(test::config_from_text(kLayer, {"solver.linear=\"mumps\""}));
  const Model mumps_compressed = test::make_model(
      test::config_from_text(kLayer, {"solver.linear=\"mumps\"", "solver.compressed_min_nodes=0"}));
  // Dense: CHOLMOD's from the trailing block of its factor, MUMPS's from K0^-1's entries.
  const Eigen::MatrixXd& W0 = *cholmod.condensation().W0().dense();
  REQUIRE(mumps.linear_solver() == "PETSc MUMPS on 1 process, with the inverse's entries on 130 interface DOFs");
  REQUIRE(mumps.condensation().W0().dense() != nullptr);
  CHECK(relative(*mumps.condensation().W0().dense(), W0) <= 1e-12);
  // Compressed from products with those entries: to the compression's accuracy.
  const DelassusOperator& W0c = mumps_compressed.condensation().W0();
  REQUIRE(W0c.compressed() != nullptr);
  REQUIRE(mumps_compressed.linear_solver() == mumps.linear_solver());  // its products need no solve of the body
  const Eigen::VectorXd y = Eigen::VectorXd::Random(W0.rows());
  Eigen::VectorXd u(W0.rows());
  W0c.multiply(y, u);
  CHECK(relative(u, W0 * y) <= 1e-9);
  for (double t : {2.0, 10.0}) CHECK(relative(mumps.condensation().q0(t), cholmod.condensation().q0(t)) <= 1e-12);
}

TEST_CASE("a floating body is refused whichever solver factorizes it", "[petsc]") {
  const Model model = test::make_model(test::config_from_text(kLayer));
  const SparseMatrix no_springs(model.stiffness().rows(), model.stiffness().cols());
  for (LinearSolver kind : {LinearSolver::Cholmod, LinearSolver::Mumps, LinearSolver::CgGamg})
    CHECK_THROWS_WITH(ElasticProblem(model.stiffness(), no_springs, {}, {}, solver(kind)),
                      Catch::Contains("not restrained"));
  // Asked for K0^-1's entries on the interface too: refused before them.
  CHECK_THROWS_WITH(ElasticProblem(model.stiffness(), no_springs, {}, read_dofs(model.interface().P),
                                   solver(LinearSolver::Mumps)),
                    Catch::Contains("not restrained"));
}

TEST_CASE("MUMPS's entries of K0^-1 on the interface give W0 and its products as its solves do", "[petsc]") {
  const Model model = test::make_model(test::config_from_text(kLayer));
  const Eigen::VectorXd one = Eigen::VectorXd::Ones(model.contact_nodes());
  const SparseMatrix springs = model.interface().springs(one, one);
  const SparseMatrix& P = model.interface().P;
  const std::vector<int> dofs = read_dofs(P);
  const ElasticProblem cholmod(model.stiffness(), springs, model.supports(), dofs, solver(LinearSolver::Cholmod));
  const ElasticProblem entries(model.stiffness(), springs, model.supports(), dofs, solver(LinearSolver::Mumps));
  const ElasticProblem solves(model.stiffness(), springs, model.supports(), {}, solver(LinearSolver::Mumps));
  REQUIRE(entries.solver_name() == "PETSc MUMPS on 1 process, with the inverse's entries on 130 interface DOFs");
  REQUIRE(solves.solver_name() == "PETSc MUMPS on 1 process");
  const Eigen::MatrixXd W = cholmod.flexibility(P);
  CHECK(relative(entries.flexibility(P), W) <= 1e-12);
  CHECK(relative(solves.flexibility(P), W) <= 1e-12);
  const Eigen::MatrixXd Y = Eigen::MatrixXd::Random(P.rows(), 5);
  CHECK(relative(entries.flexibility_products(P, Y), W * Y) <= 1e-12);
  CHECK(relative(solves.flexibility_products(P, Y), W * Y) <= 1e-12);
  // The body's full solves after the entries (MUMPS's ICNTL(30) set back) as CHOLMOD's.
  const Eigen::Index n = model.stiffness().rows();
  Eigen::MatrixXd f = Eigen::MatrixXd::Random(n, 2), u_prescribed = Eigen::MatrixXd::Zero(n, 2);
  for (int d : model.supports()) u_prescribed.row(d).setConstant(0.01);
  CHECK(relative(entries.solve(f, u_prescribed), cholmod.solve(f, u_prescribed)) <= 1e-11);
}

TEST_CASE("MUMPS out of core keeps its factor in MUMPS_OOC_TMPDIR and solves as in core", "[petsc]") {
  const Model model = test::make_model(test::config_from_text(kLayer));
  const Eigen::VectorXd one = Eigen::VectorXd::Ones(model.contact_nodes());
  const SparseMatrix springs = model.interface().springs(one, one);
  const SparseMatrix& P = model.interface().P;
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("rccm-ooc-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const OutOfCoreDirectory in(dir.string());
  LinearSolverParams ooc = solver(LinearSolver::Mumps);
  ooc.out_of_core = true;
  const ElasticProblem cholmod(model.stiffness(), springs, model.supports(), read_dofs(P), solver(LinearSolver::Cholmod));
  {
    const ElasticProblem disk(model.stiffness(), springs, model.supports(), read_dofs(P), ooc);
    CHECK(disk.solver_name() == "PETSc MUMPS on 1 process, out of core, with the inverse's entries on 130 interface DOFs");
    CHECK(!std::filesystem::is_empty(dir));  // the factor's files
    CHECK(relative(disk.flexibility(P), cholmod.flexibility(P)) <= 1e-12);
    const Eigen::Index n = model.stiffness().rows();
    const Eigen::MatrixXd f = Eigen::MatrixXd::Random(n, 2), u_prescribed = Eigen::MatrixXd::Zero(n, 2);
    CHECK(relative(disk.solve(f, u_prescribed), cholmod.solve(f, u_prescribed)) <= 1e-11);
  }
  CHECK(std::filesystem::is_empty(dir));  // removed with the factor
  std::filesystem::remove_all(dir);
  // A directory that cannot hold them: MUMPS's failure said, with where it writes.
  const OutOfCoreDirectory nowhere((dir / "missing").string());
  CHECK_THROWS_WITH(ElasticProblem(model.stiffness(), springs, model.supports(), read_dofs(P), ooc),
                    Catch::Contains("MUMPS failed (INFOG(1) = ") && Catch::Contains((dir / "missing").string() + " (MUMPS_OOC_TMPDIR)"));
}

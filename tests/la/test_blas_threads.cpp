// The BLAS's threads (la/blas_threads.hpp): one outside the large sparse work, the start-up
// count inside it, and CHOLMOD's solves right either way.
#include "rccm/la/blas_threads.hpp"
#include "rccm/la/cholmod_factor.hpp"

#include <Eigen/SparseCore>
#include <catch2/catch.hpp>
#include <omp.h>

#include <algorithm>
#include <vector>

using namespace rccm;

namespace {

/// The 1D Laplacian plus the identity: SPD, n x n.
Eigen::SparseMatrix<double> laplacian(int n) {
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, 3.0);
    if (i > 0) t.emplace_back(i, i - 1, -1.0), t.emplace_back(i - 1, i, -1.0);
  }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

}  // namespace

TEST_CASE("The BLAS has one thread outside the wide scopes and its start-up count within them", "[blas-threads]") {
  blas_threads::start();
  if (blas_threads::current() == 0) {
    WARN("the BLAS is not OpenBLAS: its threads are left as they are");
    return;
  }
  CHECK(blas_threads::current() == 1);
  // OpenMP's count for rccm's own products, no more than the cores (spinning threads beyond
  // them slow the sweeps down many times).
  CHECK(blas_threads::products() == std::min(omp_get_max_threads(), omp_get_num_procs()));
  const int threads_before = omp_get_max_threads();
  omp_set_num_threads(omp_get_num_procs() + 5);
  CHECK(blas_threads::products() == omp_get_num_procs());
  omp_set_num_threads(threads_before);
  const int wide = blas_threads::wide();
  REQUIRE(wide >= 1);
  {
    const blas_threads::Wide scope;
    CHECK(blas_threads::current() == wide);
  }
  CHECK(blas_threads::current() == 1);
  // CHOLMOD's factorization and its solves of one and of several right-hand sides: right, and
  // the BLAS back to one thread after each.
  const Eigen::SparseMatrix<double> A = laplacian(3000);
  const CholmodFactor factor(A);
  REQUIRE(factor.ok());
  CHECK(blas_threads::current() == 1);
  const Eigen::MatrixXd B = Eigen::MatrixXd::Random(3000, 16);
  for (const Eigen::MatrixXd& b : {Eigen::MatrixXd(B.leftCols(1)), B}) {
    const Eigen::MatrixXd x = factor.solve(b);
    CHECK((A * x - b).norm() <= 1e-12 * b.norm());
    CHECK(blas_threads::current() == 1);
  }
  // Several runs in one process (rccm sweep -j N): one thread in the wide scopes too.
  blas_threads::keep_one();
  {
    const blas_threads::Wide scope;
    CHECK(blas_threads::current() == 1);
  }
  CHECK(blas_threads::wide() == 1);
  CHECK(blas_threads::products() == 1);  // the compressed W0's products too (la/hodlr.cpp)
}

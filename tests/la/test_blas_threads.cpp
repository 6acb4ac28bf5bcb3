// The BLAS's threads (la/blas_threads.hpp): one outside the large sparse work, the start-up
// count inside it, and CHOLMOD's solves right either way.
#include "rccm/la/blas_threads.hpp"
#include "rccm/la/cholmod_factor.hpp"

#include <Eigen/SparseCore>
#include <catch2/catch.hpp>
#include <omp.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <fstream>
#include <string>
#include <thread>
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
    const blas_threads::Wide scope(0);  // on a free machine (a test running beside holds a core)
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

TEST_CASE("A wide scope leaves other programs' cores to them", "[blas-threads]") {
  // The BLAS's count alone; no more than the cores others leave, at least one.
  CHECK(blas_threads::wide_threads(2, 2, 0) == 2);
  CHECK(blas_threads::wide_threads(2, 2, 1) == 1);
  CHECK(blas_threads::wide_threads(2, 2, 5) == 1);
  CHECK(blas_threads::wide_threads(8, 16, 3) == 8);
  CHECK(blas_threads::wide_threads(8, 16, 12) == 4);
  CHECK(blas_threads::wide_threads(4, 2, 0) == 4);  // OPENBLAS_NUM_THREADS above the cores, asked for on a free machine
}

namespace {

/// The state letter of process `pid` ('R': runnable).
char process_state(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  std::getline(stat, line);
  return blas_threads::stat_state(line);
}

}  // namespace

TEST_CASE("A /proc stat line's state follows the last parenthesis of its command name", "[blas-threads]") {
  CHECK(blas_threads::stat_state("4242 (rccm) R 1 4242 4242 0 -1") == 'R');
  CHECK(blas_threads::stat_state("4243 (a) R (b) S 1 4242") == 'S');  // a command name "a) R (b"
  CHECK(blas_threads::stat_state("4244 (x) R") == 'R');
  CHECK(blas_threads::stat_state("") == '?');
  CHECK(blas_threads::stat_state("4245 (x)") == '?');
}

TEST_CASE("Another program's runnable thread counts and this process's own do not", "[blas-threads]") {
  if (!std::ifstream("/proc/loadavg")) {
    WARN("no /proc/loadavg: nothing to count");
    return;
  }
  // Four threads of ours spinning: were they counted, five more runnable threads (with this
  // one) would read as others. The fewest others seen in ten looks, without and then with
  // them: the machine's other programs, the same within its noise.
  const auto fewest_others = [] {
    int fewest = 1 << 30;
    for (int look = 0; look < 10; ++look) {
      fewest = std::min(fewest, blas_threads::others_running());
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return fewest;
  };
  const int before = fewest_others();
  std::atomic<bool> stop{false};
  std::vector<std::thread> spinners;
  for (int k = 0; k < 4; ++k)
    spinners.emplace_back([&stop] {
      while (!stop) {
      }
    });
  const int beside = fewest_others();
  stop = true;
  for (std::thread& t : spinners) t.join();
  INFO("other programs' runnable threads: " << before << " alone, " << beside << " beside 4 spinning threads of ours");
  CHECK(beside < before + 3);
  // A child process spinning is another program: counted at every look once it runs.
  const pid_t child = fork();
  REQUIRE(child >= 0);
  if (child == 0)
    for (;;) {
    }
  for (int wait = 0; wait < 200 && process_state(child) != 'R'; ++wait)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  int least = 1 << 30;
  for (int look = 0; look < 5; ++look) least = std::min(least, blas_threads::others_running());
  // A wide scope's threads beside it: by default the start-up count whatever the load (the same
  // bits in every rerun); following the load (OMP_DYNAMIC=true), at most the cores it leaves.
  int wide_fixed = 0, wide_following = 0;
  const bool dynamic_before = omp_get_dynamic() != 0;
  if (blas_threads::current() > 0) {
    omp_set_dynamic(0);
    CHECK(!blas_threads::follows_load());
    {
      const blas_threads::Wide scope;
      wide_fixed = blas_threads::current();
    }
    omp_set_dynamic(1);
    CHECK(blas_threads::follows_load());
    {
      const blas_threads::Wide scope;
      wide_following = blas_threads::current();
    }
  }
  omp_set_dynamic(dynamic_before);
  kill(child, SIGKILL);
  waitpid(child, nullptr, 0);
  CHECK(least >= 1);
  if (blas_threads::current() == 0) return;  // not OpenBLAS
  CHECK(wide_fixed == blas_threads::wide());
  CHECK(wide_following <= std::max(1, std::min(blas_threads::wide(), omp_get_num_procs() - 1)));
}

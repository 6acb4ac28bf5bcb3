// The BLAS's threads. CHOLMOD's supernodal kernels call the BLAS, on Debian usually OpenBLAS
// with a thread per core; after each call its idle threads spin (sched_yield) before they
// sleep. A run's solves are small and frequent (the body at each step), so the spinning threads
// took up to half of the other core (the 625-node corner peel: 62-102 s of CPU for 47-66 s of
// wall, the same run in one thread 47-62 s of CPU; docs/PERFORMANCE.md "The BLAS's threads").
// rccm therefore gives the BLAS one thread, and its own count only inside a Wide scope, around
// the large work that shares well (a sparse factorization, a block of solves).
// Without OpenBLAS (another BLAS chosen by Debian's alternatives) all of this but products()
// does nothing.
#pragma once

#include <string>

namespace rccm::blas_threads {

/// Gives the BLAS one thread (the first call of any function here does so).
void start();

/// The BLAS's threads now; 0 when the BLAS is not OpenBLAS.
int current();

/// The threads a Wide scope gives the BLAS: its own count at start-up (OPENBLAS_NUM_THREADS or
/// the cores), or 1 after keep_one().
int wide();

/// One thread everywhere from now on, Wide scopes and products() included: for several runs at
/// once in one process (`rccm sweep -j N`), whose scopes would otherwise set the BLAS's threads
/// for each other, or several processes (mpirun).
void keep_one();

/// The threads that may share rccm's own large matrix-vector products (the compressed W0's
/// blocks in a Gauss-Seidel sweep, la/hodlr.cpp; through OpenMP): OpenMP's count
/// (OMP_NUM_THREADS or the cores) but no more than the cores, or 1 after keep_one().
int most_products();

/// The threads that share them now: most_products(), at most limit_products()'s.
int products();

/// The slices rccm's own large products are cut into (the compressed W0's blocks, la/hodlr.cpp):
/// the machine's cores, however many threads compute them. Where a slice begins decides which
/// of its rows Eigen sums by packets (fused multiply-adds) and which one by one (a multiply and
/// an add, two roundings): slices fixed by the cores keep the bits the same in any thread count
/// (OMP_NUM_THREADS, keep_one, the sweeps' choice); cut by the threads, they were not.
int slices();

/// products() at most `threads` from now on (0: no limit): the sweeps' choice (thread_choice.hpp).
void limit_products(int threads);

/// Within its lifetime products() is at most `threads` (0: no limit); no limit after.
class Limit {
 public:
  explicit Limit(int threads) { limit_products(threads); }
  ~Limit() { limit_products(0); }
  Limit(const Limit&) = delete;
  Limit& operator=(const Limit&) = delete;
};

/// The threads a wide scope gives the BLAS when `others` runnable threads of other programs
/// share the machine's `cores`: `wide`, but no more than the cores they leave (at least one).
/// OpenBLAS splits each call evenly among its threads and waits for the slowest: one on a
/// core another program holds gets half of it, and the 625-node corner peel's set-up took
/// 3.5 s beside one busy process against 0.93 s in one thread.
int wide_threads(int wide, int cores, int others);

/// Runnable threads of other programs now (the kernel's count of runnable threads, less this
/// process's running ones); 0 where /proc cannot say.
int others_running();

/// The state letter of a /proc/<pid>[/task/<tid>]/stat line, "tid (comm) R ...": 'R' runnable;
/// '?' if the line has none. comm may hold spaces and parentheses: the state follows the last ')'.
char stat_state(const std::string& line);

/// Whether the wide scopes follow the load (OMP_DYNAMIC=true, or omp_set_dynamic): OpenBLAS
/// rounds a factorization in one thread differently from one in two, so a count that follows
/// the load gives reruns other bits (within the tolerances). Off by default, as OpenMP's own
/// dynamic adjustment: a rerun on the same machine gives the same bits.
bool follows_load();
/// Within its lifetime the BLAS has wide_threads(wide(), cores, others) threads; by default
/// `others` = 0 (the start-up count), where follows_load() the runnable threads of other
/// programs as the scope opens (others_running(), read only where wide() > 1); one before and after.
class Wide {
 public:
  Wide();
  explicit Wide(int others);
  ~Wide();
  Wide(const Wide&) = delete;
  Wide& operator=(const Wide&) = delete;
};

}  // namespace rccm::blas_threads

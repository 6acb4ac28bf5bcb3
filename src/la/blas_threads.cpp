#include "rccm/la/blas_threads.hpp"

#include <dlfcn.h>
#include <omp.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>

namespace rccm::blas_threads {

namespace {

using SetThreads = void (*)(int);
using GetThreads = int (*)();

/// OpenBLAS's own functions, looked up in the running program (CHOLMOD loaded the BLAS).
struct OpenBlas {
  SetThreads set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  GetThreads get = reinterpret_cast<GetThreads>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
  std::atomic<int> wide{set && get ? get() : 0};  // the BLAS's own count, before rccm changed it
  OpenBlas() {
    if (set && get) set(1);
  }
};

OpenBlas& openblas() {
  static OpenBlas blas;
  return blas;
}

std::atomic<bool> only_one{false};  // keep_one() was called
std::atomic<int> limit{0};          // limit_products()'s (0: none)

int cores() {
  static const int count = omp_get_num_procs();
  return count;
}

}  // namespace

void start() { openblas(); }

int current() {
  const OpenBlas& b = openblas();
  return b.get ? b.get() : 0;
}

int wide() { return openblas().wide; }

void keep_one() {
  OpenBlas& b = openblas();
  b.wide = b.set ? 1 : 0;
  only_one = true;
}

// More threads than cores spin against each other (OMP_NUM_THREADS=64 on 2 cores: the 625-node
// peel's contact solves 12 times as slow): at most the cores, counted once (omp_get_num_procs
// asks the kernel for the affinity at each call, and a sweep asks for each of W0's blocks).
int most_products() { return only_one ? 1 : std::max(1, std::min(omp_get_max_threads(), cores())); }

int products() {
  const int cap = limit;
  return cap > 0 ? std::min(most_products(), cap) : most_products();
}

int slices() { return cores(); }

void limit_products(int threads) { limit = threads; }

int wide_threads(int wide, int cores, int others) {
  return others > 0 ? std::max(1, std::min(wide, cores - others)) : wide;
}

int others_running() {
  std::ifstream loadavg("/proc/loadavg");  // "0.61 1.34 1.61 3/78 32075": the 4th field's first number
  double minute, five, fifteen;
  int running = 0;
  if (!(loadavg >> minute >> five >> fifteen >> running)) return 0;
  int own = 0;  // this process's threads in state R
  std::error_code error;
  for (const auto& task : std::filesystem::directory_iterator("/proc/self/task", error)) {
    std::ifstream stat(task.path() / "stat");
    std::string line;
    std::getline(stat, line);
    if (stat_state(line) == 'R') ++own;
  }
  return std::max(0, running - own);
}

char stat_state(const std::string& line) {
  const std::size_t close = line.rfind(')');
  return close != std::string::npos && close + 2 < line.size() ? line[close + 2] : '?';
}

bool follows_load() { return omp_get_dynamic() != 0; }

Wide::Wide() : Wide(openblas().set && openblas().wide > 1 && follows_load() ? others_running() : 0) {}

Wide::Wide(int others) {
  OpenBlas& b = openblas();
  if (b.set && b.wide > 1) b.set(wide_threads(b.wide, cores(), others));
}

Wide::~Wide() {
  OpenBlas& b = openblas();
  if (b.set && b.wide > 1) b.set(1);
}

}  // namespace rccm::blas_threads

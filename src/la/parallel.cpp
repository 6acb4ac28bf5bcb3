#include "rccm/la/parallel.hpp"

#include "rccm/base/errors.hpp"

#include <petscsys.h>

#include <chrono>
#include <cstdlib>
#include <mutex>
#include <thread>

namespace rccm::parallel {

namespace {

bool started = false;
int my_rank = 0, my_size = 1;

void finish() { PetscFinalize(); }

int environment_size(const char* name) {
  const char* v = std::getenv(name);
  return v ? std::atoi(v) : 1;
}

}  // namespace

bool launched() {
  // Open MPI's mpirun, and the PMI launchers of MPICH and Slurm.
  return environment_size("OMPI_COMM_WORLD_SIZE") > 1 || environment_size("PMI_SIZE") > 1;
}

void start() {
  static std::once_flag once;
  std::call_once(once, [] {
    RCCM_VERIFY(PetscOptionsSetValue(nullptr, "-no_signal_handler", nullptr) == 0, "PetscOptionsSetValue");
    RCCM_VERIFY(PetscInitializeNoArguments() == 0, "PetscInitialize");
    // Errors come back as codes, checked where they happen, without PETSc's own traces.
    PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
    MPI_Comm_rank(PETSC_COMM_WORLD, &my_rank);
    MPI_Comm_size(PETSC_COMM_WORLD, &my_size);
    started = true;
    std::atexit(finish);
  });
}

int rank() { return my_rank; }
int size() { return my_size; }

int largest(int value) {
  int all = value;
  if (my_size > 1) MPI_Allreduce(&value, &all, 1, MPI_INT, MPI_MAX, PETSC_COMM_WORLD);
  return all;
}

void abort(int status) {
  if (my_size > 1) {
    // Process 0 writes the stopped run's checkpoint and reports, then aborts everyone: the
    // others wait for that (a barrier process 0 never enters), up to a minute when it runs on.
    if (my_rank != 0) {
      MPI_Request request;
      MPI_Ibarrier(PETSC_COMM_WORLD, &request);
      int done = 0;
      for (int k = 0; k < 600 && !done; ++k) {
        MPI_Test(&request, &done, MPI_STATUS_IGNORE);
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
      }
    }
    MPI_Abort(PETSC_COMM_WORLD, status);
  }
  std::exit(status);
}

}  // namespace rccm::parallel

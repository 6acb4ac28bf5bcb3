// The processes of a run. One, unless rccm was launched by mpirun with several: then MPI and
// PETSc start with the run, every process runs the same program on the same data (the contact
// problem replicated), the body's solves are distributed (la/petsc_solver.hpp), so is ARKODE's
// state beta (time/arkode_integrator.hpp), and only process 0 writes. In one process PETSc
// starts only when a PETSc solver is asked for.
#pragma once

namespace rccm::parallel {

/// True when this process belongs to an mpirun launch of more than one process.
bool launched();

/// Starts MPI and PETSc once (later calls do nothing); they finish when the program exits.
/// PETSc's signal handlers stay off: SIGINT/SIGTERM remain rccm's (app/stop_request.hpp).
void start();

/// This process's rank and the number of processes (0 and 1 before start()).
int rank();
int size();

/// The largest of `value` over the processes, on every process (each must call it); in one
/// process, `value`.
int largest(int value);

/// Ends the program with `status`: with several processes, all of them (MPI_Abort), so that
/// none waits forever for a process that stopped on an error; a process other than 0 first
/// gives process 0 up to a minute to write its files and abort everyone itself.
[[noreturn]] void abort(int status);

}  // namespace rccm::parallel

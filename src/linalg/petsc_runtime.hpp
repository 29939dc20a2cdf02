// PETSc (and the MPI under it) is started the first time a PETSc solver is built and finalized
// at process exit, so that runs that never ask for it pay nothing. clinch runs without mpirun:
// MPI starts as a singleton, a one-rank world.
#pragma once

#include <string>

namespace clinch {

// Initializes PETSc once per process; later calls return the first outcome. False, with the
// reason in `message`, when PETSc could not start. PETSc errors are returned as codes (never
// printed, never aborting), and PETSc installs no signal handler, so that clinch's own handling of
// SIGINT and SIGTERM stays in charge.
bool ensure_petsc_initialized(std::string* message);

}  // namespace clinch

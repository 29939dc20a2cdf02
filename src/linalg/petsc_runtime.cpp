#include "src/linalg/petsc_runtime.hpp"

#include <fmt/format.h>
#include <petscsys.h>

#include <cstdlib>

#include "src/parallel/communicator.hpp"

namespace clinch {
namespace {

// Owns the PETSc session: a function-local static, so it starts on first use and finalizes
// during static destruction, after every solver held by main has been destroyed.
class PetscSession {
 public:
  PetscSession() {
    // No options from files (~/.petscrc, ./.petscrc): a run depends on its deck and command line
    // only. PETSC_OPTIONS in the environment is still read, which keeps -log_view and the
    // like available for measurements.
    static char program[] = "clinch";
    static char skip_rc[] = "-skip_petscrc";
    static char no_signals[] = "-no_signal_handler";
    static char* arguments[] = {program, skip_rc, no_signals, nullptr};
    int argc = 3;
    char** argv = arguments;
    // A run that no launcher started is a singleton, for which Open MPI would start its daemon
    // (orted) on MPI_Init and probe the high-speed network transports (PSM, PSM2) before it
    // settles on ob1: together 0.5 s of every small run with PETSc (docs/parallel.md). One
    // process talks only to itself, so isolated and with ob1 it loses nothing; a setting in the
    // environment is left alone.
    if (!launched_by_mpi()) {
      setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
      setenv("OMPI_MCA_pml", "ob1", 0);
    }
    const PetscErrorCode code = PetscInitialize(&argc, &argv, nullptr, nullptr);
    if (code != 0) {
      error_ = fmt::format("PETSc failed to initialize (error {})", static_cast<int>(code));
      return;
    }
    initialized_ = true;
    PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
  }
  ~PetscSession() {
    if (initialized_) PetscFinalize();
  }
  PetscSession(const PetscSession&) = delete;
  PetscSession& operator=(const PetscSession&) = delete;

  bool initialized() const { return initialized_; }
  const std::string& error() const { return error_; }

 private:
  bool initialized_ = false;
  std::string error_;
};

}  // namespace

bool ensure_petsc_initialized(std::string* message) {
  static const PetscSession session;
  if (!session.initialized() && message != nullptr) *message = session.error();
  return session.initialized();
}

}  // namespace clinch

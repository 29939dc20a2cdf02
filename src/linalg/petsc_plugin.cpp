// The entry points of libclinch_petsc.so, the plugin that holds the PETSc backend and the MPI
// world (petsc_plugin_loader.hpp loads it). Nothing thrown crosses them: a failure is a null
// result with its reason.
#include <exception>
#include <memory>
#include <string>
#include <type_traits>

#include "src/linalg/petsc_plugin_loader.hpp"
#include "src/linalg/petsc_runtime.hpp"
#include "src/linalg/petsc_solver.hpp"
#ifdef CLINCH_WITH_SLEPC
#include "src/linalg/slepc_eigensolver.hpp"
#endif
#include "src/parallel/communicator.hpp"

namespace clinch {
// The MPI world (src/parallel/mpi_communicator.cpp), once MPI is running; make_world_communicator
// in clinch reaches it through the plugin.
std::unique_ptr<Communicator> make_mpi_world_communicator(std::string* error);
}  // namespace clinch

extern "C" {

__attribute__((visibility("default"))) int clinch_plugin_interface_version() {
  return clinch::kPetscPluginInterface;
}

__attribute__((visibility("default"))) clinch::LinearSolver* clinch_plugin_make_petsc_solver(
    bool symmetric, bool positive_definite, std::string* error) {
  try {
    return new clinch::PetscSolver(symmetric, positive_definite);
  } catch (const std::exception& e) {
    if (error != nullptr) *error = std::string("PETSc solver: ") + e.what();
    return nullptr;
  }
}

__attribute__((visibility("default"))) clinch::Communicator* clinch_plugin_make_world_communicator(
    std::string* error) {
  try {
    // PETSc starts MPI (petsc_runtime.hpp), so that the linear solver and the exchanges share one
    // world.
    if (!clinch::ensure_petsc_initialized(error)) return nullptr;
    return clinch::make_mpi_world_communicator(error).release();
  } catch (const std::exception& e) {
    if (error != nullptr) *error = std::string("MPI world: ") + e.what();
    return nullptr;
  }
}

#ifdef CLINCH_WITH_SLEPC
__attribute__((visibility("default"))) clinch::NearestEigenpairs*
clinch_plugin_make_slepc_eigensolver(const clinch::SparseMatrix& k, const clinch::LumpedMass& mass,
                                     double shift, std::string* error) {
  try {
    return new clinch::SlepcEigensolver(k, mass, shift);
  } catch (const std::exception& e) {
    if (error != nullptr) *error = std::string("SLEPc eigensolver: ") + e.what();
    return nullptr;
  }
}
#endif

}  // extern "C"

// The signatures above are those the loader expects.
static_assert(
    std::is_same_v<decltype(clinch_plugin_interface_version), clinch::PetscPluginInterfaceVersion>);
static_assert(
    std::is_same_v<decltype(clinch_plugin_make_petsc_solver), clinch::PetscPluginMakeSolver>);
#ifdef CLINCH_WITH_SLEPC
static_assert(std::is_same_v<decltype(clinch_plugin_make_slepc_eigensolver),
                             clinch::PetscPluginMakeEigensolver>);
#endif
static_assert(std::is_same_v<decltype(clinch_plugin_make_world_communicator),
                             clinch::PetscPluginMakeWorldCommunicator>);

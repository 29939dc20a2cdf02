// The PETSc backend and the MPI world of a distributed run live in a plugin, libclinch_petsc.so,
// loaded with dlopen the first time one of them is asked for: the clinch binary links neither
// PETSc nor MPI, so that a start that never needs them (`clinch check`, a run with the default
// solvers) does not load their hundred-odd shared libraries. The plugin resolves the clinch
// functions it calls (pattern and pivot checks, share_of, fmt) from the executable that loads it,
// which therefore exports its symbols (ENABLE_EXPORTS in CMakeLists.txt).
#pragma once

#include <memory>
#include <string>
#include <utility>

#include "src/solver/frequency_eigensolver.hpp"

#include "src/linalg/linear_solver.hpp"
#include "src/parallel/communicator.hpp"

namespace clinch {

// The entry points of libclinch_petsc.so (src/linalg/petsc_plugin.cpp). A plugin whose
// clinch_plugin_interface_version differs from kPetscPluginInterface is refused.
inline constexpr int kPetscPluginInterface = 1;
extern "C" {
using PetscPluginInterfaceVersion = int();
// A new solver owned by the caller, null with the reason in `error`.
using PetscPluginMakeSolver = LinearSolver*(bool symmetric, bool positive_definite,
                                            std::string* error);
// The world communicator (make_world_communicator), null with the reason in `error`.
using PetscPluginMakeWorldCommunicator = Communicator*(std::string* error);
// SLEPc's eigensolver of K φ = λ M φ nearest σ, owned by the caller (slepc_eigensolver.hpp);
// null with the reason in `error`. A plugin built without SLEPc does not have it.
using PetscPluginMakeEigensolver = NearestEigenpairs*(const SparseMatrix& k,
                                                      const LumpedMass& mass, double shift,
                                                      std::string* error);
}

struct PetscPlugin {
  PetscPluginMakeSolver* make_solver = nullptr;
  PetscPluginMakeWorldCommunicator* make_world_communicator = nullptr;
  PetscPluginMakeEigensolver* make_eigensolver = nullptr;  // null: built without SLEPc
};

// The plugin, loaded on the first call: the file named by the environment variable
// CLINCH_PETSC_PLUGIN when it is set (and not empty), and nothing else; otherwise the first of
// libclinch_petsc.so in the directory of the running executable and in that directory's parent
// (build/tests/* find build/libclinch_petsc.so). Later calls return the first outcome. Null when
// it could not be loaded, with `error` naming every file tried and why each failed (dlerror).
const PetscPlugin* petsc_plugin(std::string* error);

// The PETSc backend (petsc_solver.hpp) from the plugin; when the plugin cannot be loaded, an
// UnavailableSolver that carries the reason.
std::unique_ptr<LinearSolver> make_petsc_solver(bool symmetric, bool positive_definite);

// SLEPc's eigensolver from the plugin; null when the plugin cannot be loaded or has no SLEPc
// (the caller then uses Spectra).
std::unique_ptr<NearestEigenpairs> make_slepc_eigensolver(const SparseMatrix& k,
                                                          const LumpedMass& mass, double shift);

// A backend that cannot be used: analyze, factorize and solve return LinearStatus::Failure with
// the reason it is unavailable.
class UnavailableSolver final : public LinearSolver {
 public:
  UnavailableSolver(const char* name, std::string reason)
      : name_(name), reason_(std::move(reason)) {}
  const char* name() const override { return name_; }
  LinearStatus analyze(const SparseMatrix&, std::string* message) override { return fail(message); }
  LinearStatus factorize(const SparseMatrix&, std::string* message) override {
    return fail(message);
  }
  LinearStatus solve(const Eigen::VectorXd&, Eigen::VectorXd&, std::string* message) override {
    return fail(message);
  }
  int failed_pivot() const override { return -1; }

 private:
  LinearStatus fail(std::string* message) const {
    if (message != nullptr) *message = reason_;
    return LinearStatus::Failure;
  }
  const char* name_;
  std::string reason_;
};

}  // namespace clinch

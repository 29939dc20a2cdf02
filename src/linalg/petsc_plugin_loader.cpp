#include "src/linalg/petsc_plugin_loader.hpp"

#include <dlfcn.h>
#include <fmt/format.h>

#include <cstdlib>
#include <filesystem>
#include <system_error>
#include <vector>

namespace clinch {
namespace {

constexpr const char* kPluginFile = "libclinch_petsc.so";

// The plugin file named by CLINCH_PETSC_PLUGIN, or null when the variable is unset or empty.
const char* chosen_plugin() {
  const char* path = std::getenv("CLINCH_PETSC_PLUGIN");
  return path != nullptr && *path != '\0' ? path : nullptr;
}

// The user's choice alone when there is one: another plugin in its place would run a build the
// user did not ask for.
std::vector<std::string> candidate_paths() {
  namespace fs = std::filesystem;
  std::vector<std::string> paths;
  if (const char* path = chosen_plugin()) {
    paths.emplace_back(path);
    return paths;
  }
  std::error_code ec;
  const fs::path executable = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path directory = executable.parent_path();
    paths.push_back((directory / kPluginFile).string());
    paths.push_back((directory.parent_path() / kPluginFile).string());
  }
  return paths;
}

std::string last_dl_error() {
  const char* text = dlerror();
  return text != nullptr ? text : "unknown error";
}

// Appends why a file failed to the list `tried`, which stays one line (it ends up in the status
// line). dlerror's messages begin with the file's path.
void note(std::string* tried, const std::string& failure) {
  *tried += fmt::format("{}{}", tried->empty() ? "" : "; ", failure);
}

// Resolves `symbol` in `handle`; null with the reason noted in `tried`.
void* resolve(void* handle, const char* symbol, std::string* tried) {
  dlerror();
  void* address = dlsym(handle, symbol);
  if (address == nullptr) note(tried, last_dl_error());
  return address;
}

struct LoadedPlugin {
  PetscPlugin plugin;
  bool loaded = false;
  std::string error;

  // Resolves the entry points of an opened plugin; false with the reason appended to `tried`.
  bool bind(void* handle, const std::string& path, std::string* tried) {
    auto* version = reinterpret_cast<PetscPluginInterfaceVersion*>(
        resolve(handle, "clinch_plugin_interface_version", tried));
    if (version == nullptr) return false;
    if (const int found = version(); found != kPetscPluginInterface) {
      note(tried, fmt::format("{}: plugin interface {}, this clinch needs {}", path, found,
                              kPetscPluginInterface));
      return false;
    }
    plugin.make_solver = reinterpret_cast<PetscPluginMakeSolver*>(
        resolve(handle, "clinch_plugin_make_petsc_solver", tried));
    plugin.make_world_communicator = reinterpret_cast<PetscPluginMakeWorldCommunicator*>(
        resolve(handle, "clinch_plugin_make_world_communicator", tried));
    // Optional: a plugin built without SLEPc lacks it.
    plugin.make_eigensolver = reinterpret_cast<PetscPluginMakeEigensolver*>(
        dlsym(handle, "clinch_plugin_make_slepc_eigensolver"));
    return plugin.make_solver != nullptr && plugin.make_world_communicator != nullptr;
  }

  LoadedPlugin() {
    std::string tried;
    for (const std::string& path : candidate_paths()) {
      // RTLD_LOCAL: PETSc's and MPI's symbols stay out of the executable's namespace.
      void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
      if (handle == nullptr) {
        note(&tried, last_dl_error());
        continue;
      }
      if (bind(handle, path, &tried)) {
        // The handle stays open for the life of the process: PETSc finalizes at exit.
        loaded = true;
        return;
      }
      plugin = {};
      dlclose(handle);
    }
    if (const char* path = chosen_plugin()) {
      error = fmt::format("the PETSc plugin '{}' that CLINCH_PETSC_PLUGIN names could not be "
                          "loaded: {}",
                          path, tried);
      return;
    }
    if (tried.empty()) {
      tried = "nothing: /proc/self/exe is unreadable and CLINCH_PETSC_PLUGIN is unset";
    }
    error = fmt::format(
        "the PETSc plugin {} could not be loaded (CLINCH_PETSC_PLUGIN names it); tried {}",
        kPluginFile, tried);
  }
};

}  // namespace

const PetscPlugin* petsc_plugin(std::string* error) {
  static const LoadedPlugin loaded;
  if (!loaded.loaded) {
    if (error != nullptr) *error = loaded.error;
    return nullptr;
  }
  return &loaded.plugin;
}

std::unique_ptr<LinearSolver> make_petsc_solver(bool symmetric, bool positive_definite) {
  std::string error;
  const PetscPlugin* plugin = petsc_plugin(&error);
  if (plugin == nullptr) return std::make_unique<UnavailableSolver>("petsc", error);
  LinearSolver* solver = plugin->make_solver(symmetric, positive_definite, &error);
  if (solver == nullptr) return std::make_unique<UnavailableSolver>("petsc", error);
  return std::unique_ptr<LinearSolver>(solver);
}

std::unique_ptr<Communicator> make_world_communicator(std::string* error) {
  const PetscPlugin* plugin = petsc_plugin(error);
  if (plugin == nullptr) return nullptr;
  return std::unique_ptr<Communicator>(plugin->make_world_communicator(error));
}

std::unique_ptr<NearestEigenpairs> make_slepc_eigensolver(const SparseMatrix& k,
                                                          const LumpedMass& mass, double shift) {
  const PetscPlugin* plugin = petsc_plugin(nullptr);
  if (plugin == nullptr || plugin->make_eigensolver == nullptr) return nullptr;
  std::string error;
  return std::unique_ptr<NearestEigenpairs>(plugin->make_eigensolver(k, mass, shift, &error));
}

}  // namespace clinch

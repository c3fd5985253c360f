#include "solver/petsc_backend.hpp"

#include <atomic>

#include "core/backend_module.hpp"

namespace magfem {
namespace {
std::atomic<PetscBackend*> loaded_backend{nullptr};
} // namespace

PetscBackend& petsc_backend() {
  // A function-local static: the first caller opens the module while concurrent callers (the
  // solves of a sweep's threads) wait; a failed open is tried again by the next call.
  static PetscBackend* const backend = [] {
    auto* opened = static_cast<PetscBackend*>(
        open_backend_module(petsc_module_file, petsc_module_entry,
                            "the iterative and distributed solvers (PETSc, MPI)"));
    loaded_backend = opened;
    return opened;
  }();
  return *backend;
}

PetscBackend* loaded_petsc_backend() {
  return loaded_backend;
}

} // namespace magfem

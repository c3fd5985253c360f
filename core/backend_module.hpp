#pragma once
// Optional backends (PETSc with MPI, VTK) live in shared modules that magfem opens the first
// time a command needs one, so that commands which never do (--version, an analytic curve, a
// 2D solve without VTU output) do not load their ~100 shared libraries at start-up (issue 35).
// The modules sit in lib/magfem beside the build tree's or the installed tree's executable and
// Python module, which find them through their run path ($ORIGIN-relative when installed).
#include <stdexcept>
#include <string>

namespace magfem {

// A backend module that is missing or cannot be loaded: an installation problem, not a bug
// nor bad input (the CLI says so and exits 1).
class BackendModuleError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

// Opens the module `file_name` (e.g. "libmagfem_petsc.so") and returns what its entry point,
// extern "C" void* `entry`(), returns: the module's backend object, which lives until the
// process ends. `needed_for` says in the error what wanted it. Each call opens the file anew
// (the dynamic loader returns the same handle); callers keep the result. Throws
// BackendModuleError naming the file, the directories searched and the loader's reason.
void* open_backend_module(const std::string& file_name, const std::string& entry,
                          const std::string& needed_for);

} // namespace magfem

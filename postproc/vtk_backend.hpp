#pragma once
// The VTK backend: VTK is called only from the module libmagfem_vtk.so (vtu_vtk_writer.cpp),
// opened the first time a process writes a .vtu. Why a module: VTK's libraries (with their
// dependencies) took a share of every command's start-up, including the many that write no
// VTU (issue 35).
#include <string>

#include "postproc/vtu_writer.hpp"

namespace magfem {

class VtkBackend {
public:
  // write_vtu of vtu_writer.hpp.
  virtual void write_vtu(const std::string& path, const VtuGrid& grid) const = 0;

protected:
  ~VtkBackend() = default;
};

inline constexpr const char* vtk_module_file = "libmagfem_vtk.so";
inline constexpr const char* vtk_module_entry = "magfem_vtk_backend";

// The backend, opening the module on the first call of the process (thread-safe). Throws
// BackendModuleError (core/backend_module.hpp) when the module cannot be loaded.
const VtkBackend& vtk_backend();

} // namespace magfem

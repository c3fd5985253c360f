#include "postproc/vtu_writer.hpp"

#include "core/backend_module.hpp"
#include "postproc/vtk_backend.hpp"
#include "postproc/vtu_unused_points.hpp"

namespace magfem {

const VtkBackend& vtk_backend() {
  // Opened once; concurrent first callers wait, and a failed open is tried again next time.
  static const VtkBackend* const backend = static_cast<const VtkBackend*>(
      open_backend_module(vtk_module_file, vtk_module_entry, "writing .vtu files (VTK)"));
  return *backend;
}

void write_vtu(const std::string& path, VtuGrid grid) {
  drop_unused_points(grid);
  vtk_backend().write_vtu(path, grid);
}

} // namespace magfem
